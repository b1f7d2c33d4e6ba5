// The static aeroelastic equilibrium of strips along beams through the runner (`analysis: static`): the strips'
// loads raised with the load factor (docs/theory.md, (A11)); docs/validation.md.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace static_aero_test {

using test::ReadFile;

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

// config/wing_aileron/flutter_eigen.yaml as a static analysis in the stream `free_stream` (a YAML flow sequence),
// with `edits` (pairs of text and its replacement) applied.
std::string WingAileronStatic(const std::string& free_stream,
                              const std::vector<std::pair<std::string, std::string>>& edits = {}) {
  std::string yaml = ReadFile(std::string(FLEXMBD_SOURCE_DIR) + "/config/wing_aileron/flutter_eigen.yaml");
  std::vector<std::pair<std::string, std::string>> all = {
      {"free_stream: [0.0, 170.0, 0.0]", "free_stream: " + free_stream}, {"analysis: eigen", "analysis: static"}};
  all.insert(all.end(), edits.begin(), edits.end());
  for (const auto& [text, replacement] : all) {
    EXPECT_NE(yaml.find(text), std::string::npos) << text;
    if (yaml.find(text) != std::string::npos) yaml.replace(yaml.find(text), text.size(), replacement);
  }
  return yaml.substr(0, yaml.find("  eigen:"));
}

TEST(StaticAero, WingAileronWithTheStreamAlongItsChordStaysWhereItIs) {
  // The root pitched 5 deg nose up (wing_aileron.urdf: -0.0872664626 rad about x) with the stream along that chord at
  // 108.656 m/s: no angle of attack, nothing to carry. It failed in load step 1 ("relative to a zero load"); each
  // load step now converges on its first iteration, whose correction is round-off (docs/theory.md, "Newton
  // iteration"), and the wing stays where it is.
  const double pitch = 0.0872664626, speed = 108.656;
  char stream[96];
  std::snprintf(stream, sizeof(stream), "[0.0, %.17g, %.17g]", speed * std::cos(pitch), -speed * std::sin(pitch));
  const test::CsvTable table =
      StaticRun("config/wing_aileron/wing_aileron.urdf", WingAileronStatic(stream), "static_wing_aileron_unloaded");
  ASSERT_FALSE(table.rows.empty());
  const std::vector<double>& equilibrium = table.rows.back();
  constexpr int kDefaultLoadSteps = 10;
  EXPECT_EQ(equilibrium.at(table.Column("solver.iterations")), kDefaultLoadSteps);
  // RoundOffFloor of the 6.1 m wing, 1.4e-13 m or rad; the stream's direction, rounded to 1e-17 rad, loads it by
  // less than that.
  constexpr double kRoundOff = 1.4e-13;
  for (const char* motion : {"ux", "uy", "uz", "rx", "ry", "rz"}) {
    EXPECT_LE(std::abs(equilibrium.at(table.Column(std::string("beam.wing.s0.") + motion))), kRoundOff) << motion;
  }
  EXPECT_LE(std::abs(equilibrium.at(table.Column("joint.aileron_hinge.position"))), kRoundOff);
}

// The free hinge (flutter_eigen.yaml without its hinge spring; `hinge` its block instead) at 5 deg and `speed`
// with `inflow_states` per strip in `load_steps`: the flap's floating angle [rad] and the tip's twist [rad].
std::pair<double, double> FreeAileronEquilibrium(double speed, int inflow_states, int load_steps,
                                                 const std::string& name, const std::string& hinge = "{}") {
  char stream[64];
  std::snprintf(stream, sizeof(stream), "[0.0, %.17g, 0.0]", speed);
  const std::string states = "inflow_states: " + std::to_string(inflow_states);
  const std::string yaml =
      WingAileronStatic(stream, {{"spring: {k: 4.12771e4, rest: 0.0}", hinge}, {"inflow_states: 6", states}}) +
      "  load_steps: " + std::to_string(load_steps) + "\n";
  const test::CsvTable table = StaticRun("config/wing_aileron/wing_aileron.urdf", yaml, name);
  if (table.rows.empty()) return {std::nan(""), std::nan("")};
  return {table.rows.back().at(table.Column("joint.aileron_hinge.position")),
          -table.rows.back().at(table.Column("beam.wing.s0.rx"))};
}

TEST(StaticAero, FreeAileronAt70MetresPerSecondFloatsAsWithQuasiSteadyStrips) {
  // The static solve failed here (2 or 20 load steps; 65 and 75 m/s converged): its simplified iteration took a
  // stale tangent's increment that the inflow states (m/s) made look contracting while the aileron's motion grew
  // from 0.05 to 0.2 m, and diverged from there. Static solves now refresh the tangent at every iteration.
  // Reference: at rest the inflow states hold Peters' steady inflow, under which a strip carries the quasi-steady
  // loads (C = 1), so the equilibrium equals that of quasi-steady strips (`inflow_states: 0`), which converged
  // before; the two solves differ by their Newton tolerances (1e-6 of the motion).
  const auto [flap, twist] = FreeAileronEquilibrium(70.0, 6, 2, "static_free_aileron_70");
  const auto [flap20, twist20] = FreeAileronEquilibrium(70.0, 6, 20, "static_free_aileron_70_20");
  const auto [flap_qs, twist_qs] = FreeAileronEquilibrium(70.0, 0, 2, "static_free_aileron_70_qs");
  std::printf("free flap at 70 m/s: %.10g rad (2 load steps), %.10g (20), quasi-steady %.10g; tip twist %.10g, %.10g, "
              "%.10g rad\n", flap, flap20, flap_qs, twist, twist20, twist_qs);
  constexpr double kSolveTolerance = 1.0e-6;
  EXPECT_NEAR(flap / flap_qs, 1.0, kSolveTolerance);
  EXPECT_NEAR(twist / twist_qs, 1.0, kSolveTolerance);
  EXPECT_NEAR(flap20 / flap_qs, 1.0, kSolveTolerance);
  EXPECT_NEAR(twist20 / twist_qs, 1.0, kSolveTolerance);
}

TEST(StaticAero, FreeAileronBetweenOpenStopsFloatsAsWithoutThem) {
  // The flap between linear stops at +-5 deg (freeplay_lco.yaml's) floats at 3.3 deg at 80 m/s, off both stops, so
  // the equilibrium is the free hinge's. It failed (any number of load steps): an open linear stop's static
  // tangent kept the stop's stiffness (docs/theory.md, (C2b)). Both solves to Newton's tolerance, 1e-6 of the
  // motion.
  const std::string stops =
      "{backlash: {lower_deg: -5.0, upper_deg: 5.0, radius_lower: 0.02032, radius_upper: 0.02032, "
      "stop: {type: elastic, law: linear, stiffness: 9.99682e7, restitution: 1.0}}}";
  const auto [flap, twist] = FreeAileronEquilibrium(80.0, 6, 10, "static_aileron_stops_80", stops);
  const auto [flap_free, twist_free] = FreeAileronEquilibrium(80.0, 6, 10, "static_free_aileron_80");
  std::printf("flap at 80 m/s between +-5 deg stops: %.10g rad, free %.10g rad; tip twist %.10g, %.10g rad\n", flap,
              flap_free, twist, twist_free);
  ASSERT_LT(std::abs(flap), 5.0 * M_PI / 180.0) << "the flap should float off its stops";
  constexpr double kSolveTolerance = 1.0e-6;
  EXPECT_NEAR(flap / flap_free, 1.0, kSolveTolerance);
  EXPECT_NEAR(twist / twist_free, 1.0, kSolveTolerance);
}

}  // namespace static_aero_test
}  // namespace flexmbd
