// Eigen-analysis about the state at chosen times of a dynamic run (solver.eigen.at_times; docs/theory.md,
// "Eigen-analysis at a time of a run"), through the runner and YAML: a pendulum swinging through states at rest
// and in motion, none of them an equilibrium.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "closed_forms.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace eigen_at_times_test {

const char kUrdf[] = "test/data/urdf/simple_pendulum.urdf";
constexpr double kG = 9.81;
// test/data/urdf/simple_pendulum.urdf: a 1 kg bob 1 m below the hinge with 1e-6 kg m^2 of its own.
constexpr double kInertiaAboutHinge = 1.0 + 1.0e-6;
constexpr double kReleaseDeg = 60.0;

// The frozen linearisation of I theta'' + m g l sin(theta) = 0 about (theta, theta', theta'') has no term in
// dtheta' and the stiffness m g l cos(theta), whatever the rate and acceleration of the state:
// f = sqrt(m g l cos(theta) / I) / (2 pi).
double FrozenFrequencyHz(double theta) { return std::sqrt(kG * std::cos(theta) / kInertiaAboutHinge) / (2 * M_PI); }

// The CSV row written at time t (every accepted step is written, and the run lands a step on t: its end time is
// the sum t_i + (t - t_i), t to a few ulp).
std::vector<double> RowAt(const test::CsvTable& csv, double t) {
  constexpr double kLanded = 1.0e-12;
  for (const std::vector<double>& row : csv.rows) {
    if (std::abs(row[0] - t) <= kLanded) return row;
  }
  return {};
}

TEST(EigenAtTimes, PendulumModeFollowsTheAngleOfTheSwing) {
  // Released at rest from 60 deg: the run lands on the release (at rest, accelerating), the bottom of the swing
  // after a quarter of the exact period 4 K(sin 30 deg) sqrt(I / (m g l)) (moving at its fastest, not
  // accelerating) and the far turning point after half of it (at rest, accelerating back). Each table is checked
  // against the frozen linearisation at the angle the CSV reports at that very step, so the phase and amplitude
  // errors of the integration do not enter. Measured: 4e-10, -1.0e-8, -9e-9 (the table's 8 printed digits).
  const double period = 4 * test::EllipticK(std::sin(kReleaseDeg * M_PI / 360)) * std::sqrt(kInertiaAboutHinge / kG);
  const double times[] = {0.0, period / 4, period / 2};
  const std::string csv_path = testing::TempDir() + "eigen_at_times_pendulum.csv";
  char yaml[512];
  std::snprintf(yaml, sizeof(yaml),
                "joints: {hinge: {initial: {position_deg: %g}}}\n"
                "solver: {t_end: %.17g, eigen: {at_times: [%.17g, %.17g, %.17g]}}\n"
                "output: {rate_hz: 0, csv: %s}\n",
                kReleaseDeg, period / 2, times[0], times[1], times[2], csv_path.c_str());
  const std::string output = test::RunnerOutput(kUrdf, yaml, "eigen_at_times_pendulum");
  const test::CsvTable csv = test::ReadCsv(csv_path);
  const size_t angle = csv.Column("joint.hinge.position");
  // The table's 8 digits, and the joint angle against the bob's rotation, which the hinge constraint ties
  // together to the Newton tolerance 1e-6 relative, times tan(theta) / 2 <= 0.87 in the frequency.
  constexpr double kFrozenTolerance = 1.0e-6;
  // A conservative system: the roots are +-i omega and the printed damping ratio is round-off.
  constexpr double kUndamped = 1.0e-9;
  for (double t : times) {
    const std::string table = test::ModeTableAt(output, t);
    ASSERT_NE(table, "") << "t " << t << "\n" << output;
    const std::vector<double> row = RowAt(csv, t);
    ASSERT_FALSE(row.empty()) << "no step lands on t = " << t;
    const test::TableRow mode = test::ModeRow(table, 1);
    EXPECT_NEAR(mode.frequency_hz / FrozenFrequencyHz(row[angle]), 1.0, kFrozenTolerance) << table;
    EXPECT_LT(std::abs(mode.damping_ratio), kUndamped) << table;
    EXPECT_TRUE(std::isnan(test::TableFrequency(table, 2))) << "one degree of freedom\n" << table;
    char error[32];
    std::snprintf(error, sizeof(error), "%.3g", mode.frequency_hz / FrozenFrequencyHz(row[angle]) - 1);
    RecordProperty("frequency_error_t_" + std::to_string(t), error);
  }
  // The states are the ones meant: the release and the far turning point at +-60 deg, the bottom at 0, within
  // the integration's amplitude and phase errors (error_tol 1e-4 per step).
  constexpr double kSwingTolerance = 1.0e-2;
  EXPECT_NEAR(RowAt(csv, times[0])[angle], kReleaseDeg * M_PI / 180, kSwingTolerance);
  EXPECT_NEAR(RowAt(csv, times[1])[angle], 0.0, kSwingTolerance);
  EXPECT_NEAR(RowAt(csv, times[2])[angle], -kReleaseDeg * M_PI / 180, kSwingTolerance);
}

}  // namespace eigen_at_times_test
}  // namespace flexmbd
