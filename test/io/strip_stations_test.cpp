// Strip stations (output.strip_stations, docs/config.md "output"): the thin-airfoil loads per unit span along a
// wing's strips, through flexmbd_run and its CSV, against the closed-form static aeroelastic twist of a uniform
// cantilever wing (test/data/yaml/wing_twist_strips.yaml, whose header gives the equations).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "../integration/helpers/runner.hpp"
#include "../integration/helpers/wing_twist_closed_form.hpp"

namespace flexmbd {
namespace strip_stations_test {

constexpr char kUrdf[] = "config/goland_wing/goland_wing.urdf";
constexpr char kConfig[] = "test/data/yaml/wing_twist_strips.yaml";

TEST(StripStations, StaticTwistOfAUniformWingMatchesTheClosedForm) {
  const std::string csv_path = testing::TempDir() + "wing_twist_strips.csv";
  ASSERT_EQ(test::RunRunner(kUrdf, kConfig, "--csv " + csv_path), 0);
  const test::CsvTable csv = test::ReadCsv(csv_path);
  ASSERT_EQ(csv.rows.size(), 1u);  // a static analysis: the equilibrium
  const std::vector<double>& row = csv.rows[0];

  const test::WingTwistClosedForm wing;
  // Bounds: cubic elements of 0.61 m with the strip loads lumped on nodes 0.2 m apart carry the twist with an
  // error of order (lambda h)^2 / 12 = 8e-5 of it, and a station between two nodes interpolates the load per
  // unit span linearly, within h^2 / 8 max|L''| = (lambda h)^2 / 8 = 1.2e-4 of it; the lift's own nonlinearity
  // (sin 2 alpha / 2 alpha at alpha < 0.004) is 1e-5. So 5e-4 of the root's lift and of the tip's twist.
  constexpr double kRelative = 5.0e-4;
  const double root_lift = wing.RootLift();
  const double tip_twist = wing.TipTwist();

  std::vector<double> inflow_per_lift;
  for (size_t k = 0; k < std::size(wing.kStations); ++k) {
    const double y = wing.kStations[k];
    const double twist = wing.Twist(y);
    const double lift = wing.Lift(y);
    const std::string strip = "strip.wing.s" + std::to_string(k) + ".";
    const std::string beam = "beam.wing.s" + std::to_string(k) + ".";
    // Nose-up twist turns about the pitch axis normal x chord = -x.
    EXPECT_NEAR(-row[csv.Column(beam + "rx")], twist, kRelative * tip_twist) << "s = " << y;
    EXPECT_NEAR(row[csv.Column(strip + "lift")], lift, kRelative * root_lift) << "s = " << y;
    EXPECT_NEAR(row[csv.Column(strip + "moment")], wing.Moment(y), kRelative * wing.arm * root_lift) << "s = " << y;
    EXPECT_EQ(row[csv.Column(strip + "hinge_moment")], 0.0);  // no flap
    inflow_per_lift.push_back(row[csv.Column(strip + "mu_1")] / row[csv.Column(strip + "lift")]);
    EXPECT_NO_THROW(csv.Column(strip + "mu_4"));
    EXPECT_THROW(csv.Column(strip + "mu_5"), std::out_of_range);
  }
  // Steady inflow (lambda = 0, (A9)): every state is a fixed multiple of w34, as the lift is, node by node; so is
  // their linear interpolation at a station (to the nonlinearity above).
  for (double ratio : inflow_per_lift) EXPECT_NEAR(ratio, inflow_per_lift[0], 1.0e-5 * std::abs(inflow_per_lift[0]));
  EXPECT_NE(inflow_per_lift[0], 0.0);
}

}  // namespace strip_stations_test
}  // namespace flexmbd
