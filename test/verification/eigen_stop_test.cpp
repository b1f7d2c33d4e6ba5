// Eigen-analysis of joints pressed on elastic stops, run the user's way (flexmbd_run on YAML in test/data/yaml),
// against the closed-form frequency of the stop's stiffness V''(a) rho^2. The analysis once took the discrete
// gradient's derivative in the end approach alone, V''/2, and gave 1/sqrt(2) of these frequencies.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "runner_output.hpp"

namespace flexmbd {
namespace eigen_stop_test {

constexpr double kPi = 3.14159265358979323846;
constexpr char kPendulumUrdf[] = "test/data/urdf/pend_rev.urdf";
// pend_rev.urdf: 1 kg at 1 m from the pivot with 1e-4 kg m^2 of its own; the YAMLs' spring (1 N m/rad) presses it
// on an upper stop of radius 0.1 m with a torque of 1 N m (rest 1 rad, stop at 0), no gravity.
constexpr double kInertia = 1.0001, kSpring = 1.0, kRadius = 0.1;

std::string DataYaml(const std::string& name) { return test::SourceText("test/data/yaml/" + name); }

double Hz(double stiffness, double inertia) { return std::sqrt(stiffness / inertia) / (2.0 * kPi); }

TEST(EigenStop, LinearStopAboutTheStaticEquilibriumHasItsFullStiffness) {
  // k rho^2 = 1e6 * 0.01 = 1e4 N m/rad in parallel with the spring: 15.9155 Hz. The equilibrium and the linear
  // law's stiffness are exact; the printed table keeps 6 significant digits (relative 5e-6 at most).
  constexpr double kPrinted = 1.0e-5;
  const std::string out = test::RunnerOutput(kPendulumUrdf, DataYaml("stop_eigen.yaml"), "stop_eigen");
  const double expected = Hz(1.0e6 * kRadius * kRadius + kSpring, kInertia);
  EXPECT_NEAR(test::TableFrequency(out, 1), expected, kPrinted * expected) << out;
}

TEST(EigenStop, HertzStopAboutTheStaticEquilibriumHasTheSlopeOfItsForce) {
  // Equilibrium: k a^1.5 rho = k_s (rest - a / rho) (the spring relaxes by the rotation a / rho into the stop), solved
  // by fixed-point iteration (it contracts by 1e-4 a step); the stiffness dF/da = 1.5 k a^0.5 times rho^2, plus
  // the spring: 13.27984 Hz (13.2805 with the spring's relaxation left out). The static solve leaves a relative
  // residual far below the 6 printed digits.
  constexpr double kPrinted = 1.0e-5;
  const std::string out = test::RunnerOutput(kPendulumUrdf, DataYaml("stop_eigen_hertz.yaml"), "stop_eigen_hertz");
  const double stiffness = 1.0e8, rest = 1.0;
  double approach = 0.0;
  for (int k = 0; k < 20; ++k) {
    approach = std::pow(kSpring * (rest - approach / kRadius) / (kRadius * stiffness), 2.0 / 3.0);
  }
  const double expected = Hz(1.5 * stiffness * std::sqrt(approach) * kRadius * kRadius + kSpring, kInertia);
  EXPECT_NEAR(test::TableFrequency(out, 1), expected, kPrinted * expected) << out;
}

TEST(EigenStop, LinearStopInContactDuringARunHasItsFullStiffness) {
  // stop_dyn2_at.yaml: released 1e-6 rad off the stop, the pendulum is in contact at t = 0.03 s (contact from
  // 1.4 ms for half a period of 31 ms), where the linear law's stiffness does not depend on the approach and the
  // restitution of 1 adds no damping: 15.9155 Hz, undamped, to the printed digits. The damping ratio is zero to
  // round-off: the state the analysis linearises about carries the round-off of the run's steps, and since the
  // elastic stop's step rules changed (C6', 2026-12-07) it prints -1.2e-37 instead of 0 (a restitution of 0.99
  // gives 0.099 here).
  constexpr double kPrinted = 1.0e-5, kRoundOff = 1.0e-15;
  const std::string out = test::RunnerOutput(kPendulumUrdf, DataYaml("stop_dyn2_at.yaml"), "stop_dyn2_at");
  const std::string table = test::ModeTableAt(out, 0.03);
  const double expected = Hz(1.0e6 * kRadius * kRadius + kSpring, kInertia);
  const test::TableRow mode = test::ModeRow(table, 1);
  EXPECT_NEAR(mode.frequency_hz, expected, kPrinted * expected) << out;
  EXPECT_LT(std::abs(mode.damping_ratio), kRoundOff) << table;
}

TEST(EigenStop, OpenRigidStopsLeaveTheSteadyRotationModesOfAHingedBlade) {
  // urotor_stops_eigen.yaml: a blade on a universal hinge of a hub at 10 rad/s, both hinge variables between open
  // rigid stops. An open stop holds lambda = 0 and nothing else; the steady-rotation Newton matrix once left that
  // row empty and failed as singular. Rotating-frame closed forms for a rigid blade on an offset hinge:
  // flap w^2 = Omega^2 (Iz - Ix + e S) / Iy + k / Iy, lag w^2 = Omega^2 e S / Iz (held hub). Printed to 6 or more
  // significant digits: relative 1e-5.
  constexpr double kPrinted = 1.0e-5;
  const std::string out =
      test::RunnerOutput("test/data/urdf/urotor.urdf", DataYaml("urotor_stops_eigen.yaml"), "urotor_stops_eigen");
  const double omega = 10.0, hinge_inertia = 5.0 / 3.0 + 5.0, axial_inertia = 0.001, offset = 0.5, first_moment = 5.0;
  const double flap_spring = 200.0;
  const double lag = Hz(omega * omega * offset * first_moment, hinge_inertia);
  const double flap =
      Hz(omega * omega * (hinge_inertia - axial_inertia + offset * first_moment) + flap_spring, hinge_inertia);
  EXPECT_EQ(test::ModeRow(out, 1).remark, "rigid body") << out;
  EXPECT_NEAR(test::TableFrequency(out, 2), lag, kPrinted * lag) << out;
  EXPECT_NEAR(test::TableFrequency(out, 3), flap, kPrinted * flap) << out;
}

TEST(EigenStop, StiffBladeOnALinearStopHasTheHingeFrequencyOfItsStop) {
  // hbeam_eigen_stiff.yaml: a 1 m blade of 2 kg/m (m_ii about y 1e-5 kg m), hinged at its root and resting on its
  // droop stop (k rho^2 = 1e4 N m/rad): rigid, sqrt(1e4 / (m L^3/3 + m_ii L)) / 2 pi = 19.4923 Hz, mode 2 (mode 1 is
  // the lag bending, EI3 1e3 N m^2: 12.5 Hz). The blade's flexibility lowers it: under the mode's inertial load
  // m w^2 x the tip moves, relative to the rigid rotation, by 11 m w^2 L^4 / (120 EI2) = 3.3e-4 in bending and
  // m w^2 L^2 / (3 GA) = 1.0e-3 in shear, so the frequency lies below the rigid one by about half of their sum,
  // 7e-4 (measured 7.2e-4; with EI2 and GA 1e11, 2.6e-6 above it). A band of 1.5e-3 below holds that; half the
  // stop's stiffness is 29% off.
  constexpr double kBladeCompliance = 1.5e-3;
  const std::string out =
      test::RunnerOutput("test/data/urdf/hbeam.urdf", DataYaml("hbeam_eigen_stiff.yaml"), "hbeam_eigen_stiff");
  const double mass = 2.0, length = 1.0, rotary = 1.0e-5;
  const double rigid = Hz(1.0e6 * kRadius * kRadius, mass * length * length * length / 3.0 + rotary * length);
  const double hinge_mode = test::TableFrequency(out, 2);
  EXPECT_LT(hinge_mode, rigid) << out;
  EXPECT_GT(hinge_mode, (1.0 - kBladeCompliance) * rigid) << out;
}

// stick_slip.urdf's 1 kg slider on a spring of 100 N/m that starts at rest on a rigid stop at 0.05 m, its rest length
// `rest`, analysed about the initial state (no static analysis).
std::string SliderOnItsStop(const std::string& rest) {
  return "joints:\n  slider:\n    spring: {k: 100.0, rest: " + rest + "}\n    initial: {position: 0.05}\n"
         "    backlash: {lower: -0.2, upper: 0.05}\n"
         "solver: {analysis: eigen}\n";
}

TEST(EigenStop, RigidStopTouchedAtTheInitialStateHoldsTheJointItsLoadPressesOnIt) {
  // The spring (rest 0.1 m) presses the slider onto its upper stop with 5 N: the stop holds it, as a step from there
  // does (eigen.at_times) and the static analysis (eigen.static_first): no degree of freedom is left. The initial
  // state has the stop open, and the analysis about it once gave a mode of sqrt(100 / 1) / 2 pi = 1.5915 Hz through
  // the stop, its reference acceleration of 5 m/s^2 into it (explore6).
  const std::string out = test::RunnerOutput("test/data/urdf/stick_slip.urdf", SliderOnItsStop("0.1"), "pressed_eigen");
  EXPECT_NE(out.find("eigen-analysis at t = 0 s (dense): 0 degrees of freedom, 0 rigid-body modes"), std::string::npos)
      << out;
}

TEST(EigenStop, RigidStopTouchedAtTheInitialStateLetsGoOfTheJointItsLoadPullsOff) {
  // The spring (rest 0) pulls the slider off the stop with 5 N: the stop would pull, so it stays open and the slider
  // oscillates on its spring, sqrt(100 / 1) / 2 pi = 1.5915494 Hz (printed to 8 digits, a relative 1e-7).
  constexpr double kPrinted = 1.0e-7;
  const std::string out = test::RunnerOutput("test/data/urdf/stick_slip.urdf", SliderOnItsStop("0.0"), "pulled_eigen");
  EXPECT_NE(out.find("1 degrees of freedom, 0 rigid-body modes"), std::string::npos) << out;
  const double expected = Hz(100.0, 1.0);
  EXPECT_NEAR(test::TableFrequency(out, 1), expected, kPrinted * expected) << out;
}

}  // namespace eigen_stop_test
}  // namespace flexmbd
