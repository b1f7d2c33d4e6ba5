// Single-degree-of-freedom checks: mass-spring on a prismatic joint, a driven joint, second-order
// convergence and adaptive stepping.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "case_builders.hpp"
#include "flexmbd/math/time_function.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace oscillator_test {

constexpr double kMass = 2.0, kStiffness = 50.0, kAmplitude = 0.1;  // [kg], [N/m], [m]

ModelSpec MassSpring(SolverSpec::Integrator integrator, double dt, double t_end) {
  return test::MassSpring(kMass, kStiffness, kAmplitude, integrator, dt, t_end);
}

double FinalPosition(const ModelSpec& spec, long* steps = nullptr) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  simulation.Run([](const OutputSample&) {});
  if (steps) *steps = simulation.statistics().accepted;
  return simulation.state().q[0];
}

TEST(MassSpring, FrequencyAndAmplitudeMatchAnalytic) {
  const double w = std::sqrt(kStiffness / kMass);
  const double period = 2 * M_PI / w;
  const Model model = BuildModel(MassSpring(SolverSpec::Integrator::kEnergyPreserving, period / 2000, 3 * period));
  Simulation simulation(model);
  double max_error = 0, max_position = 0;
  simulation.Run([&](const OutputSample& s) {
    max_error = std::max(max_error, std::abs(s.position[0] - kAmplitude * std::cos(w * s.t)));
    max_position = std::max(max_position, s.position[0]);
  });
  // Phase error of the trapezoidal family: (w h)^2 / 12 per radian, over 6 pi radians: ~5e-6 A; 1e-4 A bounds it.
  constexpr double kTrajectoryTolerance = 1.0e-4 * kAmplitude;
  EXPECT_LT(max_error, kTrajectoryTolerance);
  // The energy-preserving scheme keeps the amplitude exactly (energy identity), up to Newton tolerance.
  constexpr double kAmplitudeTolerance = 1.0e-9;
  EXPECT_NEAR(max_position, kAmplitude, kAmplitudeTolerance);
}

TEST(EnergyDecayingScheme, SecondOrderOnSmoothMotion) {
  // Error at t = 1 s against the exact cosine for dt, dt/2, dt/4: a second-order scheme divides it by ~4.
  const double w = std::sqrt(kStiffness / kMass);
  std::vector<double> errors;
  for (double dt : {0.02, 0.01, 0.005}) {
    const double x = FinalPosition(MassSpring(SolverSpec::Integrator::kEnergyDecaying, dt, 1.0));
    errors.push_back(std::abs(x - kAmplitude * std::cos(w * 1.0)));
  }
  // Observed ratios of a second-order method lie near 4; 3.5 to 4.5 rejects first (2) and third (8) order.
  for (size_t k = 1; k < errors.size(); ++k) {
    const double ratio = errors[k - 1] / errors[k];
    EXPECT_GT(ratio, 3.5) << "dt halving " << k;
    EXPECT_LT(ratio, 4.5) << "dt halving " << k;
  }
}

TEST(EnergyDecayingScheme, DampsUnresolvedModeAtRhoInf) {
  // Mass-spring stepped at w h = 1000 from a velocity kick: the unresolved mode's velocity (kinetic part,
  // dissipated at the node) and displacement (potential part, dissipated in the spring) must both shrink by
  // rho_inf per step (docs/theory.md, "High-frequency damping and rho_inf"), and the energy never rise.
  const double w = std::sqrt(kStiffness / kMass);
  constexpr double kRhoInf = 0.6;
  ModelSpec spec = MassSpring(SolverSpec::Integrator::kEnergyDecaying, 1000.0 / w, 0.0);
  spec.solver.rho_inf = kRhoInf;
  spec.solver.dt_max = spec.solver.dt;
  spec.solver.t_end = 30 * spec.solver.dt;
  spec.joints[0].initial_velocity = {1.0};
  spec.bodies[0].v_WBo_W = Vec3(1.0, 0, 0);
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  std::vector<double> speed, offset, energy;
  simulation.Run([&](const OutputSample& s) {
    speed.push_back(std::abs(s.velocity[0]));
    offset.push_back(std::abs(s.position[0]));
    energy.push_back(s.total());
  });
  ASSERT_EQ(speed.size(), 31u);
  // Geometric mean of the per-step ratio over steps 10..30, after the start-up steps (no acceleration
  // history) and the second root (~0.14) have died out; O(1/(w h)) terms shift it by ~1e-3, the gating of the
  // dissipation on single steps by ~1e-2.
  constexpr double kRateTolerance = 0.02;
  EXPECT_NEAR(std::pow(speed[30] / speed[10], 1.0 / 20.0), kRhoInf, kRateTolerance);
  EXPECT_NEAR(std::pow(offset[30] / offset[10], 1.0 / 20.0), kRhoInf, kRateTolerance);
  // The first steps have no history and preserve energy up to the Newton tolerance (1e-12 relative).
  const double round_off = 1.0e-12 * energy[0];
  for (size_t k = 1; k < energy.size(); ++k) EXPECT_LE(energy[k], energy[k - 1] + round_off) << "step " << k;
}

TEST(DrivenJoint, FollowsLawAndReportsInverseDynamicsTorque) {
  // A body with its CM on a revolute axis (no gravity torque), driven by a sine: torque = J phi''(t).
  ModelSpec spec = test::Pendulum(1.5, 0.0, 0.3);
  spec.solver.gravity = Vec3::Zero();
  TimeFunctionSpec law;
  law.kind = TimeFunctionSpec::Kind::kSine;
  law.amplitude = 0.5;
  law.frequency = 1.0;
  spec.joints[0].effects[0].drives.push_back(law);
  // Start with the drive's rate, so the motion starts smoothly.
  spec.joints[0].initial_velocity = {EvaluateRate(law, 0.0)};
  spec.bodies[0].w_WB_W = Vec3(0, EvaluateRate(law, 0.0), 0);
  spec.solver.dt = 1.0e-3;
  spec.solver.t_end = 1.0;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  double max_position_error = 0, max_torque_error = 0, late_torque_error = 0;
  simulation.Run([&](const OutputSample& s) {
    if (s.t == 0) return;
    max_position_error = std::max(max_position_error, std::abs(s.position[0] - Evaluate(law, s.t)));
    // The reported torque is the mid-step impulse over h, J (w_f - w_i)/h: compare with J phi'' at mid-step.
    const double error = std::abs(s.effort[0] - 0.3 * EvaluateSecondRate(law, s.t - 0.5 * s.dt));
    max_torque_error = std::max(max_torque_error, error);
    if (s.t > 0.5) late_torque_error = std::max(late_torque_error, error);
  });
  // The drive is a constraint solved to 1e-11 rad.
  constexpr double kPositionTolerance = 1.0e-10;
  EXPECT_LT(max_position_error, kPositionTolerance);
  // Trapezoidal velocities of a prescribed motion started at the exact rate carry an alternating mode of
  // amplitude h^2 f'''/12, which shows in the torque as J h f'''/6 (docs/theory.md, (T11)):
  // 0.3 * 1e-3 * 0.5 (2 pi)^3 / 6 = 6.2e-3 N m against a 5.9 N m peak. Allow 10% above that bound.
  const double mode_bound = 0.3 * spec.solver.dt * 0.5 * std::pow(2 * M_PI, 3) / 6.0;
  EXPECT_LT(max_torque_error, 1.1 * mode_bound);
  // The mode is smaller than h |phi''| and the energy-decaying scheme leaves modes that small alone
  // (docs/theory.md, (T11)): it must not grow.
  EXPECT_LT(late_torque_error, 1.1 * mode_bound);
}

TEST(AdaptiveStepping, ReachesAccuracyWithFewerStepsThanFixedStep) {
  // Pendulum released 1 degree from upright: a long slow phase, then a fast swing. The adaptive run's error at
  // t_end is compared with a fixed-step run using the same number of steps.
  auto pendulum = [](bool adaptive, double dt) {
    ModelSpec spec = test::Pendulum(1.0, 1.0, 1.0e-3);
    spec.joints[0].initial_position = {0.0};
    spec.bodies[0].R_WB = AxisAngle(Vec3::UnitY(), -M_PI / 2 + M_PI / 180);  // 1 degree off upright
    spec.joints[0].R_PJ = AxisAngle(Vec3::UnitY(), -M_PI / 2 + M_PI / 180);
    spec.solver.adaptive = adaptive;
    spec.solver.dt = dt;
    spec.solver.dt_max = 0.1;
    spec.solver.error_tol = 1.0e-4;
    spec.solver.t_end = 4.0;
    spec.solver.tol = 1.0e-12;
    return spec;
  };
  // Reference: a fixed step 100 times finer than the adaptive run's largest error scale ((w h)^2 ~ 1e-7).
  const double reference = FinalPosition(pendulum(false, 1.0e-4));
  long adaptive_steps = 0;
  const double adaptive_error = std::abs(FinalPosition(pendulum(true, 1.0e-3), &adaptive_steps) - reference);
  const double fixed_error = std::abs(FinalPosition(pendulum(false, 4.0 / adaptive_steps)) - reference);
  EXPECT_LT(adaptive_error, fixed_error) << "adaptive steps " << adaptive_steps;
}

}  // namespace oscillator_test
}  // namespace flexmbd
