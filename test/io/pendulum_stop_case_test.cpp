// The reference case config/pendulum_stop run by flexmbd_run: its CSV carries the stop columns
// stop.<joint>.<stop>.{in_contact,force,torque,approach} (docs/config.md, "output") with the contacts of a rod
// falling onto an elastic droop stop whose angles come from the URDF <limit>.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "../integration/helpers/runner.hpp"

namespace flexmbd {
namespace pendulum_stop_case_test {

constexpr char kUrdf[] = "config/pendulum_stop/pendulum_stop.urdf";
constexpr char kConfig[] = "config/pendulum_stop/pendulum_stop.yaml";
// The case: a 1 m, 2 kg slender rod (inertia m L^2 / 3 about the hinge), the droop stop at the URDF upper
// limit 1.0472 rad, 0.1 m from the hinge.
constexpr double kMassKg = 2.0, kLength = 1.0, kG = 9.81, kDroopAngle = 1.0472, kRadius = 0.1;

struct StopColumns {
  size_t in_contact, force, torque, approach;
};

StopColumns ColumnsOf(const test::CsvTable& csv, const std::string& stop) {
  const std::string prefix = "stop.hinge." + stop + ".";
  return {csv.Column(prefix + "in_contact"), csv.Column(prefix + "force"), csv.Column(prefix + "torque"),
          csv.Column(prefix + "approach")};
}

TEST(PendulumStopCase, CsvRecordsTheContactsOfTheDroopStop) {
  const std::string csv_path = testing::TempDir() + "pendulum_stop.csv";
  ASSERT_EQ(test::RunRunner(kUrdf, kConfig, "--csv " + csv_path), 0);
  const test::CsvTable csv = test::ReadCsv(csv_path);
  ASSERT_FALSE(csv.rows.empty());
  const StopColumns upper = ColumnsOf(csv, "upper"), lower = ColumnsOf(csv, "lower");
  const size_t position = csv.Column("joint.hinge.position"), velocity = csv.Column("joint.hinge.velocity");

  int contacts = 0;
  for (size_t k = 0; k < csv.rows.size(); ++k) {
    const std::vector<double>& row = csv.rows[k];
    EXPECT_EQ(row[lower.in_contact], 0.0) << "the rod never swings 90 deg up";
    if (row[upper.in_contact] == 0.0) {
      // The force is the step's (the effort's part): the step that leaves the contact applies the discrete gradient
      // over its whole motion (docs/theory.md (C2b)); any later one none.
      const bool leaves_contact = k > 0 && csv.rows[k - 1][upper.in_contact] != 0.0;
      if (leaves_contact) EXPECT_GE(row[upper.force], 0.0) << "row " << k;
      else EXPECT_EQ(row[upper.force], 0.0) << "row " << k;
      EXPECT_EQ(row[upper.approach], 0.0) << "row " << k;
      continue;
    }
    EXPECT_GT(row[upper.force], 0.0) << "row " << k;
    EXPECT_GT(row[upper.approach], 0.0) << "row " << k;
    // An upper stop pushes toward negative angles with the force times its radius (the CSV keeps 17 digits).
    EXPECT_DOUBLE_EQ(row[upper.torque], -kRadius * row[upper.force]) << "row " << k;
    if (k > 0 && csv.rows[k - 1][upper.in_contact] == 0.0) ++contacts;
  }
  // Restitution 0.7 keeps 0.49 of the energy per bounce: the rod bounces several times in 3 s.
  EXPECT_GE(contacts, 3);

  // The first contact: the gap closes at the droop angle, reached at the speed of a free fall from the
  // horizontal, w^2 = m g L sin(q) / I with I = m L^2 / 3. The energy-decaying scheme loses O(h^3) per step on
  // this smooth motion and the samples interpolate linearly within 1 ms steps (6e-6 relative measured): 1e-4.
  size_t first = 0;
  while (csv.rows[first][upper.in_contact] == 0.0) ++first;
  ASSERT_GT(first, 0u);
  const std::vector<double>& before = csv.rows[first - 1];
  EXPECT_LT(before[position], kDroopAngle);
  EXPECT_GE(csv.rows[first][position], kDroopAngle);
  const double inertia = kMassKg * kLength * kLength / 3.0;
  const double free_fall_rate = std::sqrt(kMassKg * kG * kLength * std::sin(before[position]) / inertia);
  constexpr double kFreeFallTolerance = 1.0e-4;
  EXPECT_NEAR(before[velocity], free_fall_rate, kFreeFallTolerance * free_fall_rate);
}

}  // namespace pendulum_stop_case_test
}  // namespace flexmbd
