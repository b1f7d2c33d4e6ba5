// Strip stations (output.strip_stations, docs/config.md "output"): the thin-airfoil loads per unit span along a
// wing's strips, through flexmbd_run and its CSV, against the closed-form static aeroelastic twist of a uniform
// cantilever wing (test/data/yaml/wing_twist_strips.yaml, whose header gives the equations).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "../integration/helpers/runner.hpp"

namespace flexmbd {
namespace {

constexpr char kUrdf[] = "config/goland_wing/goland_wing.urdf";
constexpr char kConfig[] = "test/data/yaml/wing_twist_strips.yaml";
// The case's data (the YAML file).
constexpr double kLength = 6.096, kGJ = 1.0e4, kRho = 1.225, kSemichord = 0.5, kA = -0.2;
constexpr double kStreamAlong = 20.0, kStreamUp = 0.04;
constexpr double kStations[] = {0.0, 1.0, 2.5, 4.064, 6.096};

TEST(StripStations, StaticTwistOfAUniformWingMatchesTheClosedForm) {
  const std::string csv_path = testing::TempDir() + "wing_twist_strips.csv";
  ASSERT_EQ(test::RunRunner(kUrdf, kConfig, "--csv " + csv_path), 0);
  const test::CsvTable csv = test::ReadCsv(csv_path);
  ASSERT_EQ(csv.rows.size(), 1u);  // a static analysis: the equilibrium
  const std::vector<double>& row = csv.rows[0];

  const double speed_squared = kStreamAlong * kStreamAlong + kStreamUp * kStreamUp;
  const double alpha0 = std::atan2(kStreamUp, kStreamAlong);
  const double arm = kSemichord * (0.5 + kA);  // the quarter chord ahead of the elastic axis
  const double lambda = std::sqrt(2 * M_PI * kRho * speed_squared * kSemichord * arm / kGJ);
  // Bounds: cubic elements of 0.61 m with the strip loads lumped on nodes 0.2 m apart carry the twist with an
  // error of order (lambda h)^2 / 12 = 8e-5 of it, and a station between two nodes interpolates the load per
  // unit span linearly, within h^2 / 8 max|L''| = (lambda h)^2 / 8 = 1.2e-4 of it; the lift's own nonlinearity
  // (sin 2 alpha / 2 alpha at alpha < 0.004) is 1e-5. So 5e-4 of the root's lift and of the tip's twist.
  constexpr double kRelative = 5.0e-4;
  const double root_lift = M_PI * kRho * kSemichord * speed_squared * std::sin(2 * alpha0);
  const double tip_twist = alpha0 * (1.0 / std::cos(lambda * kLength) - 1.0);

  std::vector<double> inflow_per_lift;
  for (size_t k = 0; k < std::size(kStations); ++k) {
    const double y = kStations[k];
    const double twist = alpha0 * (std::tan(lambda * kLength) * std::sin(lambda * y) + std::cos(lambda * y) - 1.0);
    // L = 2 pi rho u b w34 with u = |V| cos(alpha), w34 = |V| sin(alpha) in steady flow (theory (A8), (A9)).
    const double lift = M_PI * kRho * kSemichord * speed_squared * std::sin(2 * (alpha0 + twist));
    const std::string strip = "strip.wing.s" + std::to_string(k) + ".";
    const std::string beam = "beam.wing.s" + std::to_string(k) + ".";
    // Nose-up twist turns about the pitch axis normal x chord = -x.
    EXPECT_NEAR(-row[csv.Column(beam + "rx")], twist, kRelative * tip_twist) << "s = " << y;
    EXPECT_NEAR(row[csv.Column(strip + "lift")], lift, kRelative * root_lift) << "s = " << y;
    // Steady: the circulatory lift acts at the quarter chord, `arm` ahead of the elastic axis.
    EXPECT_NEAR(row[csv.Column(strip + "moment")], arm * lift, kRelative * arm * root_lift) << "s = " << y;
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

}  // namespace
}  // namespace flexmbd
