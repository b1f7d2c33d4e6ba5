// Natural frequencies of a slender cantilever against Euler-Bernoulli and Saint-Venant closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "beam_cases.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"

namespace flexmbd {
namespace beam_modes_test {

constexpr double kLength = 1.0, kEI = 100.0, kMass = 1.0, kGJ = 50.0, kRhoJ = 1.0e-3;
// Shear and axial stiffness 1e6 EI / L^2 and bending rotary inertia 1e-7 m make the Timoshenko corrections
// (shear ~ EI / (GA L^2), rotary inertia ~ (beta L)^2 rhoI / (m L^2)) below 1e-5 for the first three modes.
const BeamSectionSpec kSection = test::Section(1.0e8, 1.0e8, kGJ, kEI, kMass, kRhoJ, 1.0e-7);

std::vector<double> Frequencies(int elements) {
  const Model model = BuildModel(test::Cantilever(kLength, elements, 3, kSection));
  EigenOptions options;
  // The stiff axial and rotary modes reach ~1e7 rad/s, so "rigid" must mean far below 1e-6 of the largest.
  options.rigid_tolerance = 1.0e-12;
  const EigenResult result = EigenAnalysis(model, model.initial_state(), options);
  std::vector<double> f;
  for (const Mode& mode : result.modes) {
    if (!mode.rigid_body) f.push_back(mode.frequency_hz);
  }
  return f;
}

// Relative distance from `target` to the nearest computed frequency.
double NearestError(const std::vector<double>& f, double target) {
  double best = 1.0e300;
  for (double x : f) best = std::min(best, std::abs(x / target - 1.0));
  return best;
}

double BendingHz(double beta_l) {
  return beta_l * beta_l * std::sqrt(kEI / (kMass * std::pow(kLength, 4))) / (2 * M_PI);
}

TEST(BeamModes, CantileverBendingFrequenciesMatchEulerBernoulli) {
  // beta_n L = 1.8751, 4.6941, 7.8548 (clamped-free Euler-Bernoulli beam; e.g. Blevins, Formulas for Natural
  // Frequency and Mode Shape, table 8-1), each in both bending planes.
  const std::vector<double> f = Frequencies(10);
  constexpr double kTolerance = 0.005;  // the 0.5%
  for (double beta_l : {1.8751, 4.6941, 7.8548}) {
    EXPECT_LT(NearestError(f, BendingHz(beta_l)), kTolerance) << "beta L = " << beta_l;
  }
}

TEST(BeamModes, CantileverTorsionFrequencyMatchesClosedForm) {
  // First torsion mode of a clamped-free shaft: (pi / 2L) sqrt(GJ / rhoJ) / 2 pi.
  const std::vector<double> f = Frequencies(10);
  const double torsion = M_PI / (2 * kLength) * std::sqrt(kGJ / kRhoJ) / (2 * M_PI);
  constexpr double kTolerance = 0.005;
  EXPECT_LT(NearestError(f, torsion), kTolerance);
}

TEST(BeamModes, FrequencyErrorFallsWithElementCount) {
  // Convergence shown on the third bending mode: 2, 4 and 8 cubic elements.
  std::vector<double> errors;
  for (int elements : {2, 4, 8}) errors.push_back(NearestError(Frequencies(elements), BendingHz(7.8548)));
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
  RecordProperty("third_mode_error_2_4_8_elements",
                 std::to_string(errors[0]) + " " + std::to_string(errors[1]) + " " + std::to_string(errors[2]));
}

}  // namespace beam_modes_test
}  // namespace flexmbd

namespace flexmbd {
namespace beam_modes_test {

// A uniform cantilever clamped to a hub that a drive spins about z at constant speed; the state to linearise
// about is the steady rotation, with the beam stretched by its centrifugal load (u(x) = m W^2 (L^2 x / 2 -
// x^3 / 6) / EA) and every node moving on its circle.
double FirstFlapHz(double spin) {
  const double EA = 1.0e6;
  ModelSpec spec = test::Cantilever(kLength, 8, 3, test::Section(EA, 1.0e8, kGJ, kEI, kMass, kRhoJ, 1.0e-7));
  BodySpec hub;
  hub.name = "hub";
  hub.mass = 1.0;
  hub.inertia_cm_B = 0.01 * Mat3::Identity();
  hub.w_WB_W = Vec3(0, 0, spin);
  spec.bodies.push_back(hub);
  spec.joints[0].parent = "hub";  // the clamp now holds the beam on the hub
  JointSpec drive;
  drive.name = "drive";
  drive.type = JointType::kRevolute;
  drive.child = "hub";
  drive.axis_J = Vec3::UnitZ();
  drive.initial_velocity = {spin};
  drive.effects.resize(1);
  TimeFunctionSpec law;
  law.kind = TimeFunctionSpec::Kind::kLinearRamp;
  law.value = spin * 100.0;
  law.duration = 100.0;
  drive.effects[0].drives.push_back(law);
  spec.joints.push_back(drive);
  spec.beams[0].w_WB_W = Vec3(0, 0, spin);
  const Model model = BuildModel(spec);
  State state = model.initial_state();
  const BeamInfo& beam = model.beams()[0];
  for (size_t k = 0; k < beam.nodes.size(); ++k) {
    const double x = beam.stations[k];
    NodeState& n = state.nodes[beam.nodes[k]];
    n.x.x() += kMass * spin * spin * (kLength * kLength * x / 2 - x * x * x / 6) / EA;
    n.v = Vec3(0, 0, spin).cross(n.x);
  }
  EigenOptions options;
  options.rigid_tolerance = 1.0e-12;
  const EigenResult result = EigenAnalysis(model, state, options);
  // The flap (out-of-plane, z) modes: the lowest whose shape moves the tip along z.
  const int tip_z = 6 * beam.nodes.back() + 2;
  for (const Mode& mode : result.modes) {
    if (!mode.rigid_body && std::abs(mode.shape[tip_z]) > 0.5) return mode.frequency_hz;
  }
  return 0.0;
}

TEST(BeamModes, RotatingCantileverFlapFrequencyMatchesPublishedValues) {
  // Uniform cantilever, no hub radius, first flap frequency omega / sqrt(EI / (m L^4)) against the rotation
  // speed Omega / sqrt(EI / (m L^4)): Hodges and Rutkowski, AIAA J. 19 (1981) 1459-1466, Table 1 (3.5160,
  // 3.6816, 4.1373, 4.7973, 5.5850 for Omega = 0..4), also Wright et al., J. Appl. Mech. 49 (1982).
  const double scale = std::sqrt(kEI / (kMass * std::pow(kLength, 4)));
  const double published[] = {3.5160, 3.6816, 4.1373, 4.7973, 5.5850};
  for (int k = 0; k < 5; ++k) {
    const double computed = 2 * M_PI * FirstFlapHz(k * scale) / scale;
    // 8 cubic elements with lumped mass: 1e-4 on the non-rotating value; the table has five digits. 0.2%
    // covers both and the centrifugal stretch computed in closed form.
    constexpr double kTolerance = 0.002;
    EXPECT_NEAR(computed / published[k], 1.0, kTolerance) << "Omega = " << k;
  }
}

}  // namespace beam_modes_test
}  // namespace flexmbd
