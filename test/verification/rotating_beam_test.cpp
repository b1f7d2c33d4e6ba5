// Eigen-analysis about a steady rotation (docs/theory.md, "Steady rotation"), through the runner and YAML: the
// flap and lag frequencies of a uniform rotating cantilever against the published tables, the spin as a
// rigid-body mode, and the errors of a model that does not spin steadily.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/steady_rotation.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace rotating_beam_test {

const char kUrdf[] = "test/data/urdf/rotating_cantilever.urdf";
const char kYaml[] = "test/data/yaml/rotating_cantilever.yaml";

// The blade of kYaml: L = 31.623 m, m = 100 kg/m, EI = 1e8 N m^2; frequencies are made non-dimensional by
// sqrt(EI / (m L^4)) (= 0.999986 rad/s).
const double kScale = std::sqrt(1.0e8 / (100.0 * std::pow(31.623, 4)));

// First flap frequency omega / kScale of a uniform cantilever with no hub radius at the speeds lambda = Omega /
// kScale = 0, 2, ..., 12: Hodges and Rutkowski, AIAA J. 19 (1981) 1459-1466, Table 1, and Wright et al., J. Appl.
// Mech. 49 (1982) 197-202, as tabulated by Hamza-Cherif and Houmat (ICAS 2004, "Natural frequencies of rotating
// cantilever flexible beams by using the p-version of the finite element method", Table 2) for lambda 2 to 10;
// 3.5160 = 1.8751^2 (Euler-Bernoulli); 13.1702 at lambda = 12 (Hodges and Rutkowski).
const double kSpeeds[] = {0, 2, 4, 6, 8, 10, 12};
const double kFlap[] = {3.5160, 4.1373, 5.5850, 7.3603, 9.2568, 11.2023, 13.1702};

// The tables' five digits are 1.4e-5 of 3.5160 at most, and 10 cubic elements leave the flap frequencies 1e-5
// low (7e-6 at lambda 0 against 1.8751^2): 3e-5 on flap, amplified up to 5.9 times on lag (below), so 2e-4. The
// issue asks for 0.5%; measured 2.1e-5 (flap) and 4.6e-5 (lag) at worst (docs/validation.md).
constexpr double kTableTolerance = 2.0e-4;
// Lag of the same blade: the in-plane equation is the flap one plus -m Omega^2 v, so omega_lag^2 = omega_flap^2 -
// Omega^2 exactly for the inextensible beam of the tables; kYaml's EA puts the first axial mode near 5000 rad/s,
// so the axial-lag Coriolis coupling changes it by ~Omega^2 / omega_axial^2 < 1e-5. The bound is the flap one; the
// subtraction amplifies the flap error by omega_flap^2 / omega_lag^2 (5.9 at lambda 12).
double LagOf(double flap, double lambda) { return std::sqrt(flap * flap - lambda * lambda); }

std::string ReadSource(const std::string& relative) {
  std::ifstream file(std::string(FLEXMBD_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// kYaml's beam with the given joints and solver blocks.
std::string BladeWith(const std::string& joints_and_solver) {
  const std::string yaml = ReadSource(kYaml);
  return yaml.substr(0, yaml.find("\njoints:") + 1) + joints_and_solver;
}

double NonDimensional(double hz) { return 2 * M_PI * hz / kScale; }

TEST(RotatingBeam, FlapAndLagFrequenciesMatchPublishedTablesUpToSpeed12) {
  // Initial hub rate kScale, so that each velocity factor is the table's lambda; each point solves its own
  // steady state. Columns: the spin (0 Hz), then the lag and flap modes, followed across the speeds.
  std::string factors;
  for (double lambda : kSpeeds) factors += (factors.empty() ? "" : ", ") + std::to_string(static_cast<int>(lambda));
  char joints[128];
  std::snprintf(joints, sizeof(joints), "joints:\n  spin:\n    initial: {velocity: %.17g}\n", kScale);
  const std::string output = test::RunnerOutput(
      kUrdf,
      BladeWith(std::string(joints) + "solver: {gravity: [0, 0, 0], analysis: eigen, eigen: {about: steady_state, "
                                      "modes: 3, sweep: {velocity_scale: [" + factors + "]}}}\n"),
      "rotating_cantilever_sweep");
  for (size_t k = 0; k < std::size(kSpeeds); ++k) {
    const double lambda = kSpeeds[k];
    std::vector<double> row = test::FanRow(output, lambda);
    ASSERT_EQ(row.size(), 3u) << "lambda " << lambda << "\n" << output;
    std::sort(row.begin(), row.end());
    EXPECT_EQ(row[0], 0.0) << "the spin, a rigid-body mode; lambda " << lambda << "\n" << output;
    const double lag = NonDimensional(row[1]), flap = NonDimensional(row[2]);
    EXPECT_NEAR(flap / kFlap[k], 1.0, kTableTolerance) << "flap, lambda " << lambda << "\n" << output;
    EXPECT_NEAR(lag / LagOf(kFlap[k], lambda), 1.0, kTableTolerance) << "lag, lambda " << lambda << "\n" << output;
    RecordProperty("flap_lag_error_lambda_" + std::to_string(static_cast<int>(lambda)),
                   std::to_string(flap / kFlap[k] - 1) + " " + std::to_string(lag / LagOf(kFlap[k], lambda) - 1));
  }
}

TEST(RotatingBeam, SpinIsOneRigidBodyModeAndTheBendingModesAreUndamped) {
  // kYaml as it is: the blade at 6 rad/s (lambda 6.00008), where linearising about the unstretched
  // initial state gave the first flap mode at 3.5 instead of 7.36 and the spin as a damped mode. A conservative
  // gyroscopic system has purely imaginary roots: the printed damping ratios are round-off, ~eps w / |s| with the
  // frequency scale w ~ 5e4 rad/s (measured 1e-12 at most), and the report calls none unstable above -1e-9.
  const std::string output = test::RunnerOutput(kUrdf, ReadSource(kYaml), "rotating_cantilever_table");
  EXPECT_NE(output.find("1 rigid-body modes"), std::string::npos) << output;
  const test::TableRow spin = test::ModeRow(output, 1);
  EXPECT_EQ(spin.remark, "rigid body") << output;
  EXPECT_EQ(spin.frequency_hz, 0.0) << output;
  constexpr double kUndamped = 1.0e-9;
  for (int mode = 2; mode <= 4; ++mode) {
    const test::TableRow row = test::ModeRow(output, mode);
    EXPECT_LT(std::abs(row.damping_ratio), kUndamped) << "mode " << mode << "\n" << output;
    EXPECT_EQ(row.remark, "") << "mode " << mode << "\n" << output;
  }
  // lambda = 6.00008 moves the table values at 6 by 5e-6 (flap) and 1.2e-5 (lag), inside the bound.
  EXPECT_NEAR(NonDimensional(test::TableFrequency(output, 2)) / LagOf(kFlap[3], 6.0), 1.0, kTableTolerance) << output;
  EXPECT_NEAR(NonDimensional(test::TableFrequency(output, 3)) / kFlap[3], 1.0, kTableTolerance) << output;
}

TEST(RotatingBeam, SteadyStateStretchesTheBladeByItsCentrifugalLoad) {
  // test/data/yaml/spinning_blade.yaml: a 1 m blade (EA 1e7 N, m 2.5 kg/m, 4 cubic elements) on a free hub at
  // 10 rad/s, without gravity. Reference: the linear bar under m Omega^2 x, tip displacement
  // u(L) = m Omega^2 L^3 / (3 EA) = 8.333e-6 m, which the cubic elements represent exactly; the geometric
  // nonlinearity (tension on the stretched radius, the strain measure) is of the order of the strain, 1.25e-5
  // (measured 1.0e-5): 1e-4 leaves a margin of 8.
  const Model model =
      BuildModel(LoadModelSpec(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/urdf/spinning_hub.urdf",
                               std::string(FLEXMBD_SOURCE_DIR) + "/test/data/yaml/spinning_blade.yaml"));
  const SteadyRotation spin = SteadyRotationOf(model, model.initial_state());
  const SteadyResult steady = SolveSteadyRotation(model, model.initial_state(), spin);
  const double tip = steady.state.nodes[model.beams()[0].nodes.back()].x.norm() - 1.0;
  const double expected = 2.5 * 100.0 / (3 * 1.0e7);
  RecordProperty("tip_stretch_error", std::to_string(tip / expected - 1));
  constexpr double kStretchTolerance = 1.0e-4;
  EXPECT_NEAR(tip / expected, 1.0, kStretchTolerance) << tip;
  // No load turns the hub: its holding torque is round-off of the root's moments (1e-9 of m Omega^2 L^3 / 2).
  EXPECT_LT(std::abs(steady.hub_effort), 1.0e-9 * 125.0) << steady.hub_effort;
}

// The modes of kYaml's blade about the state of a dynamic run at 30 and 40 s, against those about the steady
// rotation at 6 rad/s (where the spin is a rigid-body mode, mode 1, which the drive holds in the run): lag and
// flap, frequencies and damping ratios within `tolerance` (relative). The hub is driven from rest to 6 rad/s (the
// rate following a cosine ramp over 20 s, 14 periods of the first lag mode, so that little lag motion is left),
// then held. EA is 1e9 N here, not kYaml's 1e12: the tension at the root, 1.8e6 N, is then a strain of 1.8e-3,
// which the integration resolves; at 1e12 (strain 1.8e-6) position errors of 1e-6 m per element change it
// wholesale. `beam_extra` adds keys to the beam (e.g. its damping), `solver_extra` to the run's solver block; the
// damping ratios are compared when `damped` (an undamped model's are round-off).
void ExpectRunUpModesMatchSteadyState(const std::string& beam_extra, const std::string& solver_extra, bool damped,
                                      const std::string& name, double tolerance) {
  const std::string blade = BladeWith("");
  const std::string stiff = "EA: 1.0e12";
  std::string model =
      blade.substr(0, blade.find(stiff)) + "EA: 1.0e9" + blade.substr(blade.find(stiff) + stiff.size());
  const std::string order = "    order: 3\n";
  model.insert(model.find(order) + order.size(), beam_extra);
  const std::string steady = test::RunnerOutput(
      kUrdf,
      model + "joints: {spin: {initial: {velocity: 6.0}}}\n"
              "solver: {gravity: [0, 0, 0], analysis: eigen, eigen: {about: steady_state, modes: 3}}\n",
      name + "_steady");
  const std::string run = test::RunnerOutput(
      kUrdf,
      model +
          "joints: {spin: {drive: {law: rate_ramp, rate: 6.0, duration: 20.0}}}\n"
          "solver: {" +
          solver_extra + "gravity: [0, 0, 0], t_end: 40.0, eigen: {modes: 2, at_times: [30.0, 40.0]}}\n",
      name + "_run_up");
  for (double t : {30.0, 40.0}) {
    const std::string table = test::ModeTableAt(run, t);
    ASSERT_NE(table, "") << run;
    EXPECT_NE(table.find("0 rigid-body modes"), std::string::npos) << "the drive holds the spin\n" << table;
    for (const auto& [mode, about_steady, what] : {std::make_tuple(1, 2, "lag"), std::make_tuple(2, 3, "flap")}) {
      const test::TableRow frozen = test::ModeRow(table, mode), expected = test::ModeRow(steady, about_steady);
      EXPECT_NEAR(frozen.frequency_hz / expected.frequency_hz, 1.0, tolerance)
          << what << " frequency, t " << t << "\n" << table << steady;
      if (damped) {
        EXPECT_NEAR(frozen.damping_ratio / expected.damping_ratio, 1.0, tolerance)
            << what << " damping ratio, t " << t << "\n" << table << steady;
      }
      testing::Test::RecordProperty(std::string(what) + "_error_t_" + std::to_string(static_cast<int>(t)),
                     std::to_string(frozen.frequency_hz / expected.frequency_hz - 1) + " " +
                         std::to_string(frozen.damping_ratio - expected.damping_ratio));
    }
  }
}

// What is left of the run-up oscillates undamped (but for the scheme's numerical dissipation) and modulates the
// tension: the frozen frequencies at 30 and 40 s differ from each other by 1.2e-3 (lag) and 1.7e-3 (flap), and
// from the steady ones by 9.7e-4 at most (measured), hence 2e-3. Linearising about the unstretched blade would put
// flap at half its frequency.
constexpr double kResidualTransient = 2.0e-3;

TEST(RotatingBeam, ModesAfterARunUpMatchTheSteadyStateModes) {
  ExpectRunUpModesMatchSteadyState("", "", /*damped=*/false, "rotating_cantilever_soft", kResidualTransient);
}

// With structural damping (mu = 0.05 s: damping ratios 0.078 lag, 0.045 flap about the steady state) the
// linearisation holds the damping forces' dependence on the configuration, terms of order mu EA Omega (3e8 N/m,
// the size of the axial stiffness) that cancel only in an exactly rigid rotation of the velocity field. The
// generalized-alpha run's end velocities are rigid enough: measured 4.1e-4 (lag) and 1.5e-4 (flap) from the
// steady frequencies, damping ratios 1.1e-3 and 1.0e-4, within the same residual-transient bound.
TEST(RotatingBeam, DampedModesAfterAGeneralizedAlphaRunUpMatchTheSteadyStateModes) {
  ExpectRunUpModesMatchSteadyState("    damping: 0.05\n", "integrator: generalized_alpha, ", /*damped=*/true,
                                   "rotating_cantilever_damped", kResidualTransient);
}

// The energy-decaying scheme's end velocities carry the trapezoidal relation's alternating mode (T11), with which
// the lag mode was lost among spurious overdamped roots; the analysis takes the rates extrapolated from the last
// three steps' screw motions instead (docs/theory.md (E10)), rigid in a steady rotation. What is left departs from
// rigidity by the run's own error (the flap mode holds at any tolerance; the lag damping ratio is off by 3% and
// 54% at the default error_tol 1e-4, 1.8% at 1e-5, 7e-4 at 1e-6), so the run asks for error_tol 1e-6; measured lag
// -9e-6 and -1.4e-5, flap -1e-6 and +1e-6 from the steady frequencies, damping ratios -5.1e-4 and -6.9e-4 (lag),
// flap within 1e-5, within the residual-transient bound.
TEST(RotatingBeam, DampedModesAfterAnEnergyDecayingRunUpMatchTheSteadyStateModes) {
  ExpectRunUpModesMatchSteadyState("    damping: 0.05\n", "error_tol: 1.0e-6, ", /*damped=*/true,
                                   "rotating_cantilever_damped_ed", kResidualTransient);
}

// The ConfigError of loading and building kUrdf with `yaml`, or "" if there is none.
std::string BuildError(const std::string& yaml) {
  try {
    BuildModel(LoadModelSpecFromStrings(ReadSource(kUrdf), "rotating_cantilever.urdf", YAML::Load(yaml),
                                        "steady.yaml"));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(RotatingBeam, SteadyStateSettingsAreCheckedWhenLoaded) {
  const std::string beam = BladeWith("");
  EXPECT_NE(BuildError(beam + "solver: {analysis: eigen, eigen: {about: spinning}}")
                .find("steady.yaml: solver.eigen.about"),
            std::string::npos);
  EXPECT_NE(BuildError(beam + "solver: {analysis: eigen, eigen: {about: steady_state, static_first: true}}")
                .find("steady.yaml: solver.eigen.static_first: true cannot go with about: steady_state"),
            std::string::npos);
}

TEST(RotatingBeam, ModelThatDoesNotSpinIsABadInput) {
  // No initial rate on the hub: the runner exits 2 (bad input) and names the field.
  const std::string output = test::RunnerOutput(
      kUrdf, BladeWith("solver: {analysis: eigen, eigen: {about: steady_state}}\n"), "not_spinning", 2);
  EXPECT_NE(output.find("joints.*.initial.velocity: no joint has a rate"), std::string::npos) << output;
}

}  // namespace rotating_beam_test
}  // namespace flexmbd
