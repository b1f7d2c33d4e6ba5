// The static aeroelastic equilibrium of strips along beams through the runner (`analysis: static`): the strips'
// loads raised with the load factor (docs/theory.md, (A11)); docs/validation.md.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace {

std::string ReadFile(const std::string& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

// The CSV of a static run of `urdf` with `yaml` (no `output` block), with the wing's tip as a beam station.
test::CsvTable StaticRun(const std::string& urdf, const std::string& yaml, const std::string& name) {
  const std::string csv = testing::TempDir() + name + ".csv";
  const std::string out =
      test::RunnerOutput(urdf, yaml + "output: {csv: " + csv + ", beam_stations: {wing: [6.096]}}\n", name);
  const test::CsvTable table = test::ReadCsv(csv);
  EXPECT_FALSE(table.rows.empty()) << out;
  return table;
}

// The Goland wing's beam and strips (config/goland_wing) in a static analysis with the air of `air_yaml` (keys
// under `aero:`), its tip twist [rad].
double GolandTipTwist(const std::string& air_yaml, const std::string& name) {
  const std::string yaml = std::string("beams:\n  wing:\n    length: 6.096\n    elements: 8\n") +
                           "    section: {EA: 1.0e10, GA2: 1.0e10, GA3: 1.0e10, GJ: 0.987e6, EI2: 9.77e6, EI3: 9.77e8,"
                           " m: 35.71, m_ii: [7.446, 0.016, 7.43], offsets: {cg: [0.18288, 0.0]}}\n"
                           "aero:\n" + air_yaml + "  density: 1.225\n"
                           "  strips: {wing: {beam: wing, semichord: 0.9144, a: -0.34, inflow_states: 6}}\n"
                           "solver: {analysis: static, gravity: [0.0, 0.0, 0.0]}\n";
  const test::CsvTable table = StaticRun("config/goland_wing/goland_wing.urdf", yaml, name);
  if (table.rows.empty()) return std::nan("");
  return -table.rows.back().at(table.Column("beam.wing.s0.rx"));  // nose up turns about -x
}

// The stream at alpha0 = 0.5 deg from below, at 150 m/s.
constexpr double kSpeed = 150.0, kAlpha0 = 0.5 * M_PI / 180.0;

TEST(StaticAero, GolandWingTwistsAsTheTorsionEquationOfStripTheory) {
  // Strip theory's steady moment about the elastic axis, 2 pi rho U^2 b e (alpha0 + theta), e = b (1/2 + a), twists
  // the clamped, free-tipped wing as GJ theta'' + 2 pi rho U^2 b e (alpha0 + theta) = 0: theta(L) = alpha0 (1/cos(k
  // L) - 1), k^2 = 2 pi rho U^2 b e / GJ (divergence at k L = pi/2, about 252 m/s; at 150 m/s k L = 0.934, the tip
  // twists 0.68 alpha0).
  const double rho = 1.225, b = 0.9144, a = -0.34, GJ = 0.987e6, L = 6.096;
  char stream[96];
  std::snprintf(stream, sizeof(stream), "  free_stream: [0.0, %.17g, %.17g]\n", kSpeed * std::cos(kAlpha0),
                kSpeed * std::sin(kAlpha0));
  const double twist = GolandTipTwist(stream, "static_goland");
  const double kL = std::sqrt(2.0 * M_PI * rho * kSpeed * kSpeed * b * b * (0.5 + a) / GJ) * L;
  const double expected = kAlpha0 * (1.0 / std::cos(kL) - 1.0);
  std::printf("tip twist %.6g rad, strip theory %.6g rad (k L = %.4f)\n", twist, expected, kL);
  // The strips' loads lumped on the 25 nodes integrate the moment to (k h)^2 / 12 = 1.3e-4 (h = L/24), which the
  // twist's sensitivity to k L near divergence (1.9 times here) carries; sin(alpha) and the bending's coupling
  // differ from the linear equation by (alpha0 + theta)^2 / 6 < 1e-4: 0.1% bounds both with margin (measured
  // 7e-5).
  constexpr double kTolerance = 1.0e-3;
  EXPECT_NEAR(twist / expected, 1.0, kTolerance);
}

TEST(StaticAero, GustChangingAtTheStartIsNoLoadOnTheEquilibrium) {
  // The same air with its upward part as a gust that dies out over 10 ms from t = 0: an equilibrium takes the air
  // as it is at t = 0, at rest, so the gust's rate (-100 per s, an apparent-mass load of the order of the
  // circulatory one) must not load it. The twist equals the steady stream's to the static solve's tolerance
  // (1e-6 of the motion; the two solves differ only in round-off of the air's sum).
  char stream[96], gust[160];
  std::snprintf(stream, sizeof(stream), "  free_stream: [0.0, %.17g, %.17g]\n", kSpeed * std::cos(kAlpha0),
                kSpeed * std::sin(kAlpha0));
  std::snprintf(gust, sizeof(gust),
                "  free_stream: [0.0, %.17g, 0.0]\n  gust: {velocity: [0.0, 0.0, %.17g], "
                "scale: {law: table, times: [0.0, 0.01], values: [1.0, 0.0]}}\n",
                kSpeed * std::cos(kAlpha0), kSpeed * std::sin(kAlpha0));
  const double steady = GolandTipTwist(stream, "static_goland_steady");
  const double gusting = GolandTipTwist(gust, "static_goland_gust");
  constexpr double kSolveTolerance = 1.0e-6;
  EXPECT_NEAR(gusting / steady, 1.0, kSolveTolerance) << gusting << " rad against " << steady << " rad";
}

TEST(StaticAero, WingAileronEquilibriumAt180MetresPerSecondIsFound) {
  // config/wing_aileron at 180 m/s (5 deg at the root): with the air's loads taken whole in the first load step
  // the static solve failed there; raised with the load factor it finds the equilibrium, and the same with twice
  // as many load steps (the last step's equilibrium does not depend on the path: both to Newton's tolerance, 1e-6
  // of the motion; measured 5e-14 apart, the tip twisted 0.141 rad and 0.762 m up).
  std::string yaml = ReadFile(std::string(FLEXMBD_SOURCE_DIR) + "/config/wing_aileron/flutter_eigen.yaml");
  const std::string stream = "free_stream: [0.0, 170.0, 0.0]", eigen = "analysis: eigen";
  ASSERT_NE(yaml.find(stream), std::string::npos);
  ASSERT_NE(yaml.find(eigen), std::string::npos);
  yaml.replace(yaml.find(stream), stream.size(), "free_stream: [0.0, 180.0, 0.0]");
  yaml.replace(yaml.find(eigen), eigen.size(), "analysis: static");
  yaml = yaml.substr(0, yaml.find("  eigen:"));
  const std::string urdf = "config/wing_aileron/wing_aileron.urdf";
  const test::CsvTable ten = StaticRun(urdf, yaml, "static_wing_aileron_10");
  const test::CsvTable twenty = StaticRun(urdf, yaml + "  load_steps: 20\n", "static_wing_aileron_20");
  ASSERT_FALSE(ten.rows.empty());
  ASSERT_FALSE(twenty.rows.empty());
  const double twist = -ten.rows.back().at(ten.Column("beam.wing.s0.rx"));
  const double again = -twenty.rows.back().at(twenty.Column("beam.wing.s0.rx"));
  std::printf("tip twist at 180 m/s: %.8g rad (10 load steps), %.8g rad (20)\n", twist, again);
  constexpr double kPathTolerance = 1.0e-6;
  EXPECT_NEAR(again / twist, 1.0, kPathTolerance);
}

}  // namespace
}  // namespace flexmbd
