// Eigen-analysis at the limits of round-off (docs/theory.md, (E5), (E6)), through the runner and YAML: elastic
// roots far below the highest frequency are not taken for rigid-body modes, and roots of neutral motions that
// round-off moves off the axis are not taken for instabilities, while a genuine instability is still reported.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "runner_output.hpp"

namespace flexmbd {
namespace eigen_round_off_test {

// A uniform cantilever, L = 1 m, EI2 = 100 N m^2, m = 0.5 kg/m, stiff in shear and extension, no gravity, with
// rotary inertia m_ii about its bending axes: the rotations of its nodes, sqrt(stiffness / m_ii), reach ~1e8 times
// its first bending frequency.
std::string CantileverYaml(int elements, const std::string& rotary_inertia) {
  return "beams:\n  arm: {length: 1.0, elements: " + std::to_string(elements) +
         ", section: {EA: 1.0e9, GA2: 1.0e9, GA3: 1.0e9, GJ: 100.0, EI2: 100.0, EI3: 1.0e4, m: 0.5, m_ii: [1.0e-3, " +
         rotary_inertia + ", " + rotary_inertia +
         "]}}\nsolver: {analysis: eigen, gravity: [0, 0, 0], eigen: {modes: 3}}\n";
}

// Euler-Bernoulli clamped-free beam: f1 = (beta1 L)^2 / (2 pi L^2) sqrt(EI / m), beta1 L = 1.875104 (Blevins,
// Formulas for Natural Frequency and Mode Shape, table 8-1): 7.913815 Hz.
double FirstBendingHz() { return 1.875104 * 1.875104 / (2 * M_PI) * std::sqrt(100.0 / 0.5); }

TEST(EigenRoundOff, FineClampedBeamKeepsItsFundamentalWithTheSparseMethod) {
  // 300 cubic elements (5406 unknowns: the sparse method) with m_ii = 1e-9 kg m: frequency scale 5.2e9 rad/s, the
  // fundamental (50 rad/s) at 1e-8 of it. The dense solvers' rigid-body test at 1e-8 of the scale printed it as
  // "0 Hz, rigid body"; the sparse method judges zero roots against its shift (1e-2 of its offset, 1e-8 of the scale).
  // 1e-4: measured 8.8e-6 from the closed form (the round-off of a spectrum spread over 1e8; the 20-element mesh of
  // the same beam at m_ii = 1e-9, spread 1e7: 4e-7), far inside the loss of the mode.
  const std::string out =
      test::RunnerOutput("test/data/urdf/cantilever.urdf", CantileverYaml(300, "1.0e-9"), "fine_cantilever");
  constexpr double kTolerance = 1.0e-4;
  EXPECT_NE(out.find("(sparse shift-invert): 5400 degrees of freedom, 0 rigid-body modes"), std::string::npos) << out;
  EXPECT_NEAR(test::TableFrequency(out, 1) / FirstBendingHz(), 1.0, kTolerance) << out;
}

// The number of modes the runner's table calls unstable.
int UnstableRows(const std::string& out) {
  int count = 0;
  for (size_t at = out.find("unstable ("); at != std::string::npos; at = out.find("unstable (", at + 1)) ++count;
  return count;
}

TEST(EigenRoundOff, RotationOfAFreeHubIsARigidBodyModeNotADivergence) {
  // test/data/urdf/light_hub_rotor.urdf: hub (Izz = 1 kg m^2) free about z at W = 10 rad/s, blade m = 5 kg on a
  // universal hinge at e = 0.5 m, centre of mass d = 1 m beyond it, inertias about the hinge Ixx = 0.001,
  // Iyy = Izz = 1.6667 + m d^2, flap spring 200 N m/rad: a relative equilibrium. The rotation of the whole about z is
  // a rigid-body mode; the accelerations the analysis solves for are 4.5e-10 off (the round-off of (E2)), which
  // made it a real pair +-1.9e-4 1/s, one printed as "unstable (divergence)", and no rigid-body mode.
  const std::string yaml =
      "joints:\n  spin: {initial: {velocity: 10.0}}\n  root:\n    type: universal\n    axis: [0, 1, 0]\n"
      "    axis2: [0, 0, 1]\n    variables:\n      - {spring: {k: 200.0}}\n"
      "solver: {analysis: eigen, gravity: [0, 0, 0]}\n";
  const std::string out = test::RunnerOutput("test/data/urdf/light_hub_rotor.urdf", yaml, "light_hub_rotor");
  EXPECT_NE(out.find("3 degrees of freedom, 1 rigid-body modes"), std::string::npos) << out;
  EXPECT_EQ(UnstableRows(out), 0) << out;
  const double w = 10.0, m = 5.0, e = 0.5, d = 1.0, k = 200.0, i_axial = 0.001,
               i_cross = 1.6666666666666667 + m * d * d;
  // Flap (about the hinge's y): (k + W^2 (m e d + Izz - Ixx)) / Iyy.
  const double flap = std::sqrt((k + w * w * (m * e * d + i_cross - i_axial)) / i_cross) / (2 * M_PI);
  // Lag with the hub free: m W^2 e d / (Izz - Mpz^2 / Mpp), Mpz = Izz + m e d the lag's coupling to the spin and
  // Mpp = 1 + 1.6667 + m (e + d)^2 the inertia of the whole about the axis.
  const double coupling = i_cross + m * e * d, axial = 1.0 + 1.6666666666666667 + m * (e + d) * (e + d);
  const double lag = std::sqrt(m * w * w * e * d / (i_cross - coupling * coupling / axial)) / (2 * M_PI);
  EXPECT_EQ(test::ModeRow(out, 1).remark, "rigid body") << out;
  EXPECT_NEAR(test::TableFrequency(out, 2) / flap, 1.0, test::kPrintedTolerance) << out;
  EXPECT_NEAR(test::TableFrequency(out, 3) / lag, 1.0, test::kPrintedTolerance) << out;
}

constexpr double kSpin = 2.0;
const char kSpinYaml[] = "joints:\n  spin: {initial: {velocity: 2.0}}\nsolver: {analysis: eigen, gravity: [0, 0, 0]}\n";

TEST(EigenRoundOff, FreeTranslationsSeenFromASpinningBodyAreNoFlutter) {
  // A free body spinning at W = 2 rad/s about its major axis (1.5, 2, 3 kg m^2), seen from its own frame: the free
  // translations across the axis turn at +-W, a double root of the first-order form that round-off split into
  // damping ratios of +-1.3e-8, one printed as "unstable (flutter)". The wobble (Euler's equations):
  // W sqrt((I3 - I1)(I3 - I2) / (I1 I2)).
  const std::string out = test::RunnerOutput("test/data/urdf/free_body_major_axis.urdf", kSpinYaml, "major_axis");
  EXPECT_NE(out.find("3 rigid-body modes"), std::string::npos) << out;
  EXPECT_EQ(UnstableRows(out), 0) << out;
  const double wobble = kSpin * std::sqrt((3.0 - 1.5) * (3.0 - 2.0) / (1.5 * 2.0)) / (2 * M_PI);
  EXPECT_NEAR(test::TableFrequency(out, 4) / wobble, 1.0, test::kPrintedTolerance) << out;
  for (int mode = 5; mode <= 7; ++mode) {
    EXPECT_NEAR(test::TableFrequency(out, mode) / (kSpin / (2 * M_PI)), 1.0, test::kPrintedTolerance) << out;
  }
}

TEST(EigenRoundOff, SpinAboutTheIntermediateAxisIsStillADivergence) {
  // The same with the spin about the intermediate axis (1, 3, 2 kg m^2): the tilt grows as exp(s t),
  // s = W sqrt((I2 - I3)(I3 - I1) / (I1 I2)) = 1.1547 1/s (the tennis racket), the one unstable mode; the free
  // translations at +-W are neutral as above.
  const std::string out =
      test::RunnerOutput("test/data/urdf/free_body_intermediate_axis.urdf", kSpinYaml, "intermediate_axis");
  ASSERT_EQ(UnstableRows(out), 1) << out;
  int divergence = 0;
  for (int mode = 1; mode <= 8; ++mode) {
    if (test::ModeRow(out, mode).remark == "unstable (divergence)") divergence = mode;
  }
  ASSERT_GT(divergence, 0) << out;
  const double growth = kSpin * std::sqrt((3.0 - 2.0) * (2.0 - 1.0) / (1.0 * 3.0));
  EXPECT_NEAR(2 * M_PI * test::TableFrequency(out, divergence) / growth, 1.0, test::kPrintedTolerance) << out;
  EXPECT_EQ(test::ModeRow(out, divergence).damping_ratio, -1.0) << out;
}

}  // namespace eigen_round_off_test
}  // namespace flexmbd
