// Static analysis against closed-form equilibria.

#include <gtest/gtest.h>

#include <cmath>

#include "case_builders.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace {

TEST(StaticAnalysis, PendulumWithTorsionalSpringBalancesGravity) {
  // Arm upright at phi = 0 (CM at height l above the pivot), torsional spring k, gravity -z: equilibrium
  // k phi = m g l sin(phi). With m g l / k = 2 the nontrivial root is phi* = 1.895494267...
  const double m = 2.0, l = 0.5, g = 9.81, k = m * g * l / 2.0;
  ModelSpec spec = test::Pendulum(m, l, 1.0e-2);
  const Mat3 R_up = AxisAngle(Vec3::UnitY(), -M_PI / 2);  // arm along +z at phi = 0
  spec.joints[0].R_PJ = R_up;
  spec.joints[0].effects[0].springs.push_back({k, 0.0});
  // Start away from the unstable upright equilibrium.
  const double phi0 = 1.0;
  spec.joints[0].initial_position = {phi0};
  spec.bodies[0].R_WB = R_up * AxisAngle(Vec3::UnitY(), phi0);
  spec.solver.analysis = SolverSpec::Analysis::kStatic;
  spec.solver.load_steps = 1;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  simulation.Run([](const OutputSample&) {});
  const double phi = simulation.state().q[0];
  // Residual of the closed form at the computed angle, relative to the spring torque: Newton to 1e-12.
  constexpr double kBalanceTolerance = 1.0e-9;
  EXPECT_NEAR((k * phi - m * g * l * std::sin(phi)) / (k * phi), 0.0, kBalanceTolerance);
  EXPECT_NEAR(phi, 1.8954942670339809, 1.0e-9);
}

TEST(StaticAnalysis, StaticFirstStartsDynamicsAtRest) {
  // The same pendulum, with static_first and a dynamic run: started from the static equilibrium it must stay
  // there. Reference: the equilibrium angle 1.8954942670339809 of k phi = m g l sin(phi).
  const double m = 2.0, l = 0.5, g = 9.81, k = m * g * l / 2.0;
  ModelSpec spec = test::Pendulum(m, l, 1.0e-2);
  const Mat3 R_up = AxisAngle(Vec3::UnitY(), -M_PI / 2);
  spec.joints[0].R_PJ = R_up;
  spec.joints[0].effects[0].springs.push_back({k, 0.0});
  spec.joints[0].initial_position = {1.0};
  spec.bodies[0].R_WB = R_up * AxisAngle(Vec3::UnitY(), 1.0);
  spec.solver.static_first = true;
  spec.solver.load_steps = 1;
  spec.solver.dt = 1.0e-2;
  spec.solver.t_end = 2.0;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  double worst_drift = 0;
  simulation.Run([&](const OutputSample& s) { worst_drift = std::max(worst_drift, std::abs(s.position[0] - 1.8954942670339809)); });
  // Equilibrium to Newton accuracy; the dynamics then see residual forces of order 1e-12 relative only.
  constexpr double kDriftTolerance = 1.0e-9;
  EXPECT_LT(worst_drift, kDriftTolerance);
}

}  // namespace
}  // namespace flexmbd
