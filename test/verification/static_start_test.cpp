// A dynamic run started from its static equilibrium (solver.static_first) with a drive that moves at t = 0 starts
// with the drive's rate, and everything else at rest relative to what carries it (docs/theory.md (K4)); through
// the runner and YAML at default settings, as a user runs it. Before (K4) every rate started at zero and the
// first step jumped to the drive's motion: the double pendulum below lost 9.0 J in it. The eigen-analysis about the
// equilibrium takes no drive rate.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace static_start_test {

constexpr double kPi = 3.14159265358979323846;
// The shoulder's sine of the defect: 20 deg at 1.5 Hz, f'(0) = 20 deg x 2 pi 1.5 Hz [rad/s].
constexpr double kAmplitude = 20.0 * kPi / 180.0, kFrequency = 1.5;
constexpr double kDriveRate = kAmplitude * 2.0 * kPi * kFrequency;
const char* const kSine = "{law: sine, amplitude_deg: 20.0, frequency: 1.5}";
// Start rates and energies come from one linear solve and the CSV's 17 digits: round-off.
constexpr double kRoundOff = 1.0e-12;

// Runs `yaml` (output.csv appended) through the runner on a URDF of the source tree; returns the CSV.
test::CsvTable RunToCsv(const std::string& urdf, const std::string& yaml, const std::string& name) {
  const std::string csv = testing::TempDir() + name + ".csv";
  const std::string out = test::RunnerOutput(urdf, yaml + "output: {rate_hz: 1000, csv: " + csv + "}\n", name);
  EXPECT_NE(out.find("finished at t = "), std::string::npos) << out;
  return test::ReadCsv(csv);
}

double At(const test::CsvTable& table, size_t row, const std::string& column) {
  return table.rows.at(row).at(table.Column(column));
}

// The largest energy lost up to t_until: E0 + external work - E - physical dissipation, the numerical dissipation
// of the scheme (T6) [J].
double NumericalLossUntil(const test::CsvTable& table, double t_until) {
  const double first = At(table, 0, "energy.total");
  double worst = 0;
  for (size_t i = 0; i < table.rows.size() && At(table, i, "t") <= t_until; ++i) {
    worst = std::max(worst, first + At(table, i, "energy.external_work") - At(table, i, "energy.total") -
                                At(table, i, "energy.dissipated"));
  }
  return worst;
}

// On a resolved motion of frequency w the energy-decaying scheme dissipates per step alpha m w_t . (v_f - v_i) (T6),
// w_t = O(h^2 a'): about alpha (w h)^3 of the kinetic energy, so over a time T about alpha T w^3 h^2. With
// alpha_inf = 0.047 (rho_inf 0.6), w = 9.4 rad/s, T = 0.1 s and steps h <= 0.01 s that is at most 4e-4 of the
// start's kinetic energy; the bound is 1e-3. The jump to the drive's rate from rest dissipated about all of it
// (1.0 of the start's kinetic energy for the link, 0.9 for the double pendulum).
constexpr double kLossPerStartEnergy = 1.0e-3;
constexpr double kFirstSteps = 0.1;  // [s]

// A link on a pivot, its centre of mass at l = 1 m (test/data/urdf/pend_rev.urdf: 1 kg, I_yy 1e-4 kg m^2 about its
// centre), driven by the sine: at t = 0 the pivot turns at f'(0), the link's centre moves at f'(0) l, so the
// kinetic energy is (m l^2 + I_yy) f'(0)^2 / 2; over the first steps the joint rate follows f'(t) and the books
// lose nothing.
TEST(StaticStart, ADrivenLinkStartsAtItsDrivesRateTimesItsLever) {
  const test::CsvTable table = RunToCsv("test/data/urdf/pend_rev.urdf",
                                        std::string("joints: {pivot: {drive: ") + kSine + "}}\n"
                                        "solver: {static_first: true, t_end: 0.2}\n",
                                        "static_start_link");
  ASSERT_GT(table.rows.size(), 100u);
  constexpr double kMass = 1.0, kLever = 1.0, kInertia = 1.0e-4;
  const double start_energy = 0.5 * (kMass * kLever * kLever + kInertia) * kDriveRate * kDriveRate;
  EXPECT_NEAR(At(table, 0, "joint.pivot.velocity"), kDriveRate, kRoundOff * kDriveRate);
  EXPECT_NEAR(At(table, 0, "energy.kinetic"), start_energy, kRoundOff * start_energy);
  // The end rates carry the trapezoidal relation's alternating mode, h^2 |f'''| / 12 (T11), and samples between
  // steps interpolate linearly (h^2 |f''| / 8): with h <= 0.01 s, |f'''| <= A w^3 = 292 rad/s^3 and
  // |f''| <= A w^2 = 31 rad/s^2 that is 2.8e-3 rad/s at most.
  const double w = 2.0 * kPi * kFrequency, h = 0.01;
  const double rate_tolerance = h * h * (kAmplitude * w * w * w / 12.0 + kAmplitude * w * w / 8.0);
  double worst_rate = 0;
  for (size_t i = 0; i < table.rows.size() && At(table, i, "t") <= kFirstSteps; ++i) {
    const double f_rate = kDriveRate * std::cos(w * At(table, i, "t"));
    worst_rate = std::max(worst_rate, std::abs(At(table, i, "joint.pivot.velocity") - f_rate));
  }
  RecordProperty("worst_rate_error", std::to_string(worst_rate));
  EXPECT_LE(worst_rate, rate_tolerance);
  const double loss = NumericalLossUntil(table, kFirstSteps);
  RecordProperty("loss_per_start_energy", std::to_string(loss / start_energy));
  EXPECT_LE(loss, kLossPerStartEnergy * start_energy);
}

// The defect as found: config/double_pendulum's arm with the shoulder on the sine, the elbow with friction and
// rigid stops, gravity. The elbow hangs in the equilibrium and starts at rest relative to the upper arm, so the
// whole arm turns rigidly about the shoulder at f'(0): kinetic energy I f'(0)^2 / 2 with I the arm's moment of
// inertia about the shoulder axis at the elbow's static angle; the first steps lose nothing.
TEST(StaticStart, TheDoublePendulumStartsWithItsElbowAtRestAndLosesNothing) {
  const test::CsvTable table =
      RunToCsv("config/double_pendulum/double_pendulum.urdf",
               std::string("joints:\n  shoulder: {drive: ") + kSine + "}\n"
               "  elbow:\n    initial: {position_deg: 60.0}\n"
               "    friction: {mu_k: 0.1, mu_s: 0.15, radius: 0.02}\n"
               "    backlash: {lower_deg: 30.0, upper_deg: 120.0}\n"
               "solver: {static_first: true, t_end: 0.5}\n",
               "static_start_double_pendulum");
  ASSERT_GT(table.rows.size(), 100u);
  EXPECT_NEAR(At(table, 0, "joint.shoulder.velocity"), kDriveRate, kRoundOff * kDriveRate);
  EXPECT_NEAR(At(table, 0, "joint.elbow.velocity"), 0.0, kRoundOff * kDriveRate);
  // Links of double_pendulum.urdf: 2 kg with its centre 0.5 m out, 1 kg with its centre 0.4 m beyond the elbow
  // 1 m out, I_yy 0.16667 and 0.05333 kg m^2 about their centres; the upper arm horizontal (f(0) = 0).
  const double elbow = At(table, 0, "joint.elbow.position");
  const double forearm_x = 1.0 + 0.4 * std::cos(elbow), forearm_z = 0.4 * std::sin(elbow);
  const double inertia = 0.16667 + 2.0 * 0.5 * 0.5 + 0.05333 + 1.0 * (forearm_x * forearm_x + forearm_z * forearm_z);
  const double start_energy = 0.5 * inertia * kDriveRate * kDriveRate;
  EXPECT_NEAR(At(table, 0, "energy.kinetic"), start_energy, kRoundOff * start_energy);
  const double loss = NumericalLossUntil(table, kFirstSteps);
  RecordProperty("loss_per_start_energy", std::to_string(loss / start_energy));
  EXPECT_LE(loss, kLossPerStartEnergy * start_energy);
}

// test/data/yaml/rotating_cantilever.yaml with its hub's spin joint on the sine and a static start.
std::string BladeOnADrivenHubYaml() {
  std::string yaml = test::SourceText("test/data/yaml/rotating_cantilever.yaml");
  yaml = test::Replaced(yaml, "initial: {velocity: 6.0}", std::string("drive: ") + kSine);
  return test::Replaced(yaml, "  analysis: eigen\n  eigen: {about: steady_state, modes: 4}\n",
                        "  static_first: true\n");
}

// A blade bent by its weight (the blade above with gravity along the spin axis, 1.2 m of droop at the tip): the
// static start carries the bent blade rigidly with the hub, with no strain rate ((K4)): every node moves at w x x and
// turns at w, w = f'(0) about z through the origin, to round-off of the blade's speed w L.
TEST(StaticStart, ABentBladeOnADrivenHubStartsTurningRigidly) {
  const std::string yaml =
      test::Replaced(BladeOnADrivenHubYaml(), "gravity: [0.0, 0.0, 0.0]", "gravity: [0.0, 0.0, -9.81]");
  const std::string file = testing::TempDir() + "static_start_blade.yaml";
  std::ofstream(file) << yaml;
  const Model model =
      BuildModel(LoadModelSpec(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/urdf/rotating_cantilever.urdf", file));
  Simulation simulation(model);
  simulation.SolveStaticStart();
  const State& state = simulation.state();
  const Vec3 spin(0.0, 0.0, kDriveRate);
  const double speed = kDriveRate * 31.623;  // at the tip [m/s]
  ASSERT_LT(state.nodes[model.beams().front().nodes.back()].x.z(), -1.0);  // bent
  for (int k = 0; k < model.num_nodes(); ++k) {
    const NodeState& n = state.nodes[k];
    EXPECT_LE((n.v - spin.cross(n.x)).norm(), kRoundOff * speed) << model.node_name(k);
    EXPECT_LE((n.R * n.w - spin).norm(), kRoundOff * kDriveRate) << model.node_name(k);
  }
}

// The same blade in 120 elements (n = 2,173), through the runner: beyond the dense solve's limit the start is refused
// (a solver error, exit 3) in a message that says how to start such a model, not left to run for minutes or to
// exhaust the memory.
TEST(StaticStart, ALargeModelWithAMovingDriveIsRefusedWithTheWayOut) {
  const std::string yaml = test::Replaced(BladeOnADrivenHubYaml(), "elements: 10", "elements: 120");
  const std::string output =
      test::RunnerOutput("test/data/urdf/rotating_cantilever.urdf", yaml, "static_start_long_blade", 3);
  EXPECT_NE(output.find("up to 2000 kinematic unknowns; this model has 2173. Expected a drive at rest at the start (a "
                        "cosine_ramp), or solver.static_first: false"),
            std::string::npos)
      << output;
}

// test/data/yaml/slider_crank.yaml's loop (a spherical crank pin, a universal wrist pin closing it) with its crank
// on a sine of 1 rad at 1 Hz and gravity: one degree of freedom, which the drive takes, so the equilibrium is the
// loader's assembly, and the static start's rates (K4) are those the loader gives the same drive rate (K3), the
// least change of the undriven rates that keeps the loop closed: every joint rate and the kinetic energy agree to
// round-off.
TEST(StaticStart, ADrivenLoopStartsWithTheRatesOfTheLoadersAssembly) {
  std::string yaml = test::SourceText("test/data/yaml/slider_crank.yaml");
  yaml = test::Replaced(yaml, "{law: cosine_ramp, value: 12.566370614359172, duration: 2.0}",
                        "{law: sine, amplitude: 1.0, frequency: 1.0}");
  yaml = test::Replaced(yaml, "output: {rate_hz: 0}", "");
  auto start = [&](const std::string& static_first, const std::string& name) {
    return RunToCsv("test/data/urdf/slider_crank.urdf",
                    test::Replaced(yaml, "solver: {t_end: 2.5, gravity: [0.0, 0.0, 0.0]}",
                                   "solver: {t_end: 0.01, static_first: " + static_first + "}"),
                    name);
  };
  const test::CsvTable statics = start("true", "static_start_loop"), assembled = start("false", "assembled_loop");
  ASSERT_FALSE(statics.rows.empty() || assembled.rows.empty());
  const double crank_rate = 2.0 * kPi;  // f'(0) [rad/s]; the slider's speed is of the crank's radius times it
  for (const std::string& column : statics.header) {
    if (column.find(".velocity") == std::string::npos && column != "energy.kinetic") continue;
    EXPECT_NEAR(At(statics, 0, column), At(assembled, 0, column), kRoundOff * crank_rate) << column;
  }
  EXPECT_GT(At(statics, 0, "energy.kinetic"), 0.0);
}

// config/double_pendulum as it is (its shoulder on a cosine ramp, whose rate at t = 0 is zero) with a static start:
// the run starts at rest, every rate and the kinetic energy exactly zero, as before (K4).
TEST(StaticStart, ADriveAtRestAtTheStartLeavesEveryRateZero) {
  std::string yaml = test::SourceText("config/double_pendulum/double_pendulum.yaml");
  yaml = test::Replaced(yaml, "t_end: 10.0", "t_end: 1.0");
  yaml = test::Replaced(yaml, "output: {rate_hz: 100}\n", "  static_first: true\n");
  const test::CsvTable table = RunToCsv("config/double_pendulum/double_pendulum.urdf", yaml, "static_start_ramp");
  ASSERT_FALSE(table.rows.empty());
  EXPECT_EQ(At(table, 0, "joint.shoulder.velocity"), 0.0);
  EXPECT_EQ(At(table, 0, "joint.elbow.velocity"), 0.0);
  EXPECT_EQ(At(table, 0, "energy.kinetic"), 0.0);
}

// The eigen-analysis about the static equilibrium (solver.eigen.static_first) linearises about the state at rest,
// whatever the drives' rates: the sine (f''(0) = 0) gives the mode of the shoulder held by a constant drive, to the
// table's 8 digits. It once reported a divergence at 14.6 Hz: (E2) differenced the drive's law across its start
// and read its jump of rate as an acceleration.
TEST(StaticStart, AnEigenAnalysisAboutTheEquilibriumTakesNoDriveRate) {
  auto mode = [](const std::string& drive, const std::string& name) {
    const std::string yaml = "joints:\n  shoulder: {drive: " + drive + "}\n"
                             "  elbow: {initial: {position_deg: 60.0}, spring: {k: 5.0}}\n"
                             "solver: {analysis: eigen, eigen: {static_first: true}}\n";
    return test::ModeRow(test::RunnerOutput("config/double_pendulum/double_pendulum.urdf", yaml, name), 1);
  };
  const test::TableRow moving = mode(kSine, "static_eigen_sine");
  const test::TableRow held = mode("{law: constant, value: 0.0}", "static_eigen_held");
  EXPECT_EQ(moving.remark, held.remark);
  EXPECT_NEAR(moving.frequency_hz, held.frequency_hz, test::kPrintedTolerance * held.frequency_hz);
  EXPECT_NEAR(moving.damping_ratio, held.damping_ratio, test::kPrintedTolerance * std::abs(held.damping_ratio));
}

}  // namespace static_start_test
}  // namespace flexmbd
