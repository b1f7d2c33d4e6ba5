// Distributed loads on beams (docs/theory.md, (B9)): consistent nodal loads of a uniform load per length.

#include <gtest/gtest.h>

#include <cmath>

#include "beam_cases.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace beam_loads_test {

constexpr double kLength = 1.0, kEI = 100.0, kMass = 1.0;

TEST(BeamLoads, UniformDeadLoadDeflectsTipByQL4Over8EI) {
  // Euler-Bernoulli cantilever under a uniform load q: tip deflection q L^4 / (8 EI) (e.g. Roark's Formulas,
  // table 8.1 case 2a). q L^3 / EI = 1e-4 keeps the geometric nonlinearity at ~1e-8 relative; GA = 1e6 EI / L^2
  // adds the shear deflection q L^2 / (2 GA) = 4e-6 relative. The uniform load's consistent nodal loads are
  // exact and 4 cubic elements leave the quartic deflection's tip value well below that (measured total 4.0e-6).
  constexpr double q = 0.01;
  ModelSpec spec = test::Cantilever(kLength, 4, 3, test::Section(1.0e8, 1.0e8, 50.0, kEI, kMass, 1.0e-3, 1.0e-3));
  spec.loads.push_back(test::DistributedLoad(LoadSpec::Kind::kForce, LoadSpec::Frame::kWorld, Vec3(0, 0, -q)));
  spec.solver.analysis = SolverSpec::Analysis::kStatic;
  spec.solver.tol = 1.0e-10;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  simulation.Run([](const OutputSample&) {});
  const double tip = simulation.state().nodes[model.beams()[0].nodes.back()].x.z();
  constexpr double kRelativeTolerance = 1.0e-5;
  EXPECT_NEAR(tip / (-q * std::pow(kLength, 4) / (8 * kEI)), 1.0, kRelativeTolerance);
  RecordProperty("tip_error", test::Figure(tip / (-q * std::pow(kLength, 4) / (8 * kEI)) - 1.0));
}

TEST(BeamLoads, UniformDeadMomentTurnsTipByML2Over2EI) {
  // A uniform moment m per length about z: bending moment m (L - s), tip rotation m L^2 / (2 EI) whatever
  // its size (planar bending, moments about a fixed axis; closed form). Taken to 0.5 rad: large rotation.
  // The nodal moments are exact; the curvature is linear in s, which cubic elements represent: the
  // tolerance is the static solver's (1e-10 relative residual).
  constexpr double kTipAngle = 0.5, kRelativeTolerance = 1.0e-6;
  ModelSpec spec = test::Cantilever(kLength, 4, 3, test::Section(1.0e8, 1.0e8, 50.0, kEI, kMass, 1.0e-3, 1.0e-3));
  spec.loads.push_back(test::DistributedLoad(LoadSpec::Kind::kMoment, LoadSpec::Frame::kWorld,
                                   Vec3(0, 0, 2 * kEI * kTipAngle / (kLength * kLength))));
  spec.solver.analysis = SolverSpec::Analysis::kStatic;
  spec.solver.tol = 1.0e-10;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  simulation.Run([](const OutputSample&) {});
  const Vec3 rotation = Log(simulation.state().nodes[model.beams()[0].nodes.back()].R);
  EXPECT_NEAR(rotation.z() / kTipAngle, 1.0, kRelativeTolerance);
}

// A stiff beam on a hinge about z at its root, pushed by a uniform load q across it in its own section frame
// (y): the load turns with the beam, so its moment about the hinge stays q L^2 / 2 and the hinge angle is
// phi = (q L^2 / 2) t^2 / (2 I), I = m L^3 / 3 + rhoI_z L (closed form of a rigid bar under a constant torque).
// A dead load would lose its moment as cos(phi).
double HingedBeamAngle(LoadSpec::Frame frame, double t_end, double dt) {
  // One cubic element: its lumped masses give m L^3 / 3 exactly (the 3/8 rule integrates s^2 exactly).
  ModelSpec spec = test::Cantilever(kLength, 1, 3, test::Section(1.0e8, 1.0e8, 1.0e4, 1.0e4, kMass, 1.0e-3, 1.0e-3));
  spec.joints[0].type = JointType::kRevolute;
  spec.joints[0].axis_J = Vec3::UnitZ();
  spec.loads.push_back(test::DistributedLoad(LoadSpec::Kind::kForce, frame, Vec3(0, 1.0, 0)));
  spec.solver.integrator = SolverSpec::Integrator::kEnergyPreserving;
  spec.solver.adaptive = false;
  spec.solver.dt = dt;
  spec.solver.t_end = t_end;
  spec.solver.tol = 1.0e-10;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  double angle = 0.0;
  simulation.Run([&](const OutputSample& s) { angle = s.position[0]; });
  return angle;
}

TEST(BeamLoads, FollowerLoadKeepsItsMomentAboutTheHinge) {
  constexpr double t_end = 1.5, dt = 1.25e-3;
  const double inertia = kMass * std::pow(kLength, 3) / 3 + 1.0e-3 * kLength;
  const double expected = 0.5 * kLength * kLength / (2 * inertia) * t_end * t_end;  // 1.68 rad
  // The beam bends under the net load q - m s phi'' by ~q L^4 / (30 EI) = 3e-6 L, which changes the moment
  // arm by that much. The nodes turn on circles in Cartesian coordinates: the scheme's error is O((w h)^2),
  // measured 2.3e-4 at w h = 6e-3 (about 6 (w h)^2); here w h <= 2.8e-3, i.e. 5e-5. 1e-4 covers both.
  constexpr double kRelativeTolerance = 1.0e-4;
  const double follower = HingedBeamAngle(LoadSpec::Frame::kBody, t_end, dt);
  EXPECT_NEAR(follower / expected, 1.0, kRelativeTolerance);
  RecordProperty("follower_angle_error", test::Figure(follower / expected - 1.0));
  // The dead load of the same size falls behind: its moment fades as cos(phi) (8% behind at 1.5 s).
  EXPECT_LT(HingedBeamAngle(LoadSpec::Frame::kWorld, t_end, 4 * dt), 0.95 * expected);
}

}  // namespace beam_loads_test
}  // namespace flexmbd
