// The rotor engage model of issue 18 (config/rotor_engage, docs/cases.md), first milestone: the articulated
// three-bladed rotor with its swash plates, scissors and beam pitch links loads, the loader assembles its five
// loops about the controls set through the universal and prismatic joints, and the static analysis under gravity
// converges. Reference: the linkage's kinematics, blade pitch theta(psi) = theta_0 + theta_1c cos(psi) +
// theta_1s sin(psi) at each pitch link's azimuth psi.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace rotor_engage_test {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr double kCollective = 3.0 * kDegree, kLongitudinal = 2.5 * kDegree, kLateral = 0.0693 * kDegree;
// The pitch link of blade k stands 26.565 deg (atan(0.15 / 0.30): horn arm over hinge offset) ahead of the blade.
constexpr double kLinkLead = 26.56505117707799 * kDegree;
// The YAML sets the controls to first order: the foot of a pitch link rises a sin(theta_0) + r (phi_1 sin(psi) -
// phi_2 cos(psi)), which turns the blade by asin(rise / a). With the cyclic part d (up to 2.5 deg) the pitch
// differs from theta_0 + d by d (1 / cos(theta_0) - 1) + tan(theta_0) d^2 / 2 + d^3 / 6 = 1.3e-4 rad at most;
// the pitch link's tilt as the horn swings in (a (1 - cos(theta)) = 7e-4 m over 0.6 m) shortens its reach by
// 4e-7 m (3e-6 rad), and gravity loads the pitch links little (each blade's centre of mass on its pitch axis).
// 2e-4 rad bounds the sum (measured 1.7e-5 to 9.1e-5 rad).
constexpr double kPitchTolerance = 2.0e-4;

ModelSpec RotorStatic() {
  const std::string folder = std::string(FLEXMBD_SOURCE_DIR) + "/config/rotor_engage/";
  return LoadModelSpec(folder + "rotor_engage.urdf", folder + "rotor_engage_static.yaml");
}

TEST(RotorEngage, ControlsSetTheBladePitchThroughTheAssembledLinkage) {
  const Model model = BuildModel(RotorStatic());
  Simulation simulation(model);
  OutputSample equilibrium;
  simulation.Run([&](const OutputSample& s) { equilibrium = s; });
  for (int k = 0; k < 3; ++k) {
    const double psi = 2.0 * 3.14159265358979323846 * k / 3.0 + kLinkLead;
    const double expected = kCollective + kLateral * std::cos(psi) + kLongitudinal * std::sin(psi);
    const int pitch = model.FindVariable("pitch_" + std::to_string(k));
    EXPECT_NEAR(model.initial_state().q[pitch], expected, kPitchTolerance) << "assembled, blade " << k;
    EXPECT_NEAR(equilibrium.position[pitch], expected, kPitchTolerance) << "static, blade " << k;
    // each blade held on its droop stop in the static analysis
    EXPECT_NEAR(equilibrium.position[model.FindVariable("flap_" + std::to_string(k))], -0.54 * kDegree, 1e-12);
  }
}

std::string ReadCase(const std::string& file) {
  std::ifstream in(std::string(FLEXMBD_SOURCE_DIR) + "/config/rotor_engage/" + file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RotorEngage, RunnerSolvesTheStaticEquilibrium) {
  const std::string output = test::RunnerOutput("config/rotor_engage/rotor_engage.urdf",
                                                ReadCase("rotor_engage_static.yaml"), "rotor_engage_static");
  EXPECT_NE(output.find("finished at t = 0 s; 1 samples written"), std::string::npos) << output;
}

// The start of the first contact interval the runner lists for `stop` ("stop flap_0 lower: 1 contact interval(s)
// [a, b] s"), and the interval's text; NaN if there is none.
std::pair<double, std::string> FirstContact(const std::string& output, const std::string& stop) {
  const size_t at = output.find(stop + ": ");
  if (at == std::string::npos) return {std::nan(""), ""};
  const std::string line = output.substr(at, output.find('\n', at) - at);
  const size_t open = line.find('[');
  if (open == std::string::npos) return {std::nan(""), line};
  return {std::stod(line.substr(open + 1)), line};
}

TEST(RotorEngage, BladesSettleOntoTheirDroopStopsAsTheRunUpStarts) {
  // The run-up's first 0.1 s in the published gust (CI's short version of rotor_engage.yaml, 30 s): released on
  // their droop stops, the blades press them from the first step (measured 0.3 ms) to the end; the flap stops,
  // 2.04 deg above, stay clear: at rest speed the gust's 5.3 m/s downward pushes every blade down, whichever edge
  // the 19.9 m/s side wind meets first (docs/theory.md, (A12)).
  std::string yaml = ReadCase("rotor_engage.yaml");
  const std::string full_run = "t_end: 30.0";
  ASSERT_NE(yaml.find(full_run), std::string::npos);
  yaml.replace(yaml.find(full_run), full_run.size(), "t_end: 0.1");
  const std::string output = test::RunnerOutput("config/rotor_engage/rotor_engage.urdf", yaml, "rotor_engage_short");
  EXPECT_NE(output.find("finished at t = 0.1 s"), std::string::npos) << output;
  constexpr double kWithinAMillisecond = 1.0e-3;
  for (int k = 0; k < 3; ++k) {
    const std::string stop = "stop flap_" + std::to_string(k);
    const auto [start, droop] = FirstContact(output, stop + " lower");
    EXPECT_NE(droop.find(": 1 contact interval(s)"), std::string::npos) << droop;
    EXPECT_LT(start, kWithinAMillisecond) << droop;
    EXPECT_NE(droop.find(", 0.1] s"), std::string::npos) << droop;  // to the end
    EXPECT_NE(output.find(stop + " upper: 0 contact interval(s)"), std::string::npos) << output;
  }
}

}  // namespace rotor_engage_test
}  // namespace flexmbd
