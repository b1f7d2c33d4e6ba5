// Commands from a controller (docs/theory.md, "Commands"): a commanded effort enters the variable's equation
// and its work is booked as external work; a set-point leads a drive along a first-order lag.

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "case_builders.hpp"
#include "flexmbd/common/error.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace commands_test {

constexpr double kMass = 1.0, kArm = 0.5, kInertiaCm = 0.02, kGravity = 9.81;
constexpr double kAngle = 0.5;   // initial angle below the horizontal [rad]
constexpr double kNewtonTol = 1.0e-12;

// The test pendulum (case_builders.hpp) released at rest at kAngle below the horizontal, fixed steps of 10 ms.
ModelSpec TiltedPendulum() {
  ModelSpec spec = test::Pendulum(kMass, kArm, kInertiaCm);
  spec.bodies[0].R_WB = Eigen::AngleAxisd(kAngle, Vec3::UnitY()).toRotationMatrix();
  spec.joints[0].initial_position = {kAngle};
  spec.solver.dt = 0.01;
  spec.solver.t_end = 2.0;
  spec.solver.tol = kNewtonTol;
  return spec;
}

// Gravity's generalised force on the pivot angle q (positive down from the horizontal): m g arm cos q.
double GravityTorque(double q) { return kMass * kGravity * kArm * std::cos(q); }

TEST(CommandedEffort, HoldsAPendulumAgainstGravity) {
  const Model model = BuildModel(TiltedPendulum());
  Simulation simulation(model);
  simulation.SetEffort(0, -GravityTorque(kAngle));
  double worst_angle = 0, worst_effort = 0;
  simulation.Integrate(model.solver().t_end, [&](const OutputSample& s) {
    worst_angle = std::max(worst_angle, std::abs(s.position[0] - kAngle));
    // t = 0 reports the initial multipliers, zero without a static analysis; the steps' efforts follow
    if (s.t > 0) worst_effort = std::max(worst_effort, std::abs(s.effort[0] + GravityTorque(kAngle)));
  });
  // Closed form: the commanded torque balances gravity exactly, so the pendulum stays at rest. What moves it is
  // the Newton residual left in each step, at most tol times the torques (m g arm cos q = 4.3 N m): an angle
  // offset of tol m g arm cos q / (m g arm cos q) = tol against the restoring stiffness, oscillating without
  // growth about the equilibrium (stable: cos q > 0). 100 tol leaves room for round-off in the 200 steps.
  constexpr double kHoldTolerance = 100 * kNewtonTol;
  EXPECT_LT(worst_angle, kHoldTolerance);
  // The pivot reports the commanded effort as the torque it transmits (docs/ros.md, "Effort"): it carries the
  // whole gravity load, to the same relative tolerance.
  EXPECT_LT(worst_effort, kHoldTolerance * GravityTorque(kAngle));
}

TEST(CommandedEffort, ItsWorkIsExternalWorkAndTheBooksClose) {
  const Model model = BuildModel(TiltedPendulum());
  Simulation simulation(model);
  constexpr double kEffort = 3.0;  // [N m], turns the arm down through the hanging position and back
  simulation.SetEffort(0, kEffort);
  OutputSample first, last;
  bool have_first = false;
  simulation.Integrate(model.solver().t_end, [&](const OutputSample& s) {
    if (!have_first) first = s, have_first = true;
    last = s;
  });
  // A constant effort u does the work u (q(T) - q(0)) exactly, whatever path q took: the element books u dq per
  // step, so the sum telescopes to round-off (1e-15 relative per step, 200 steps).
  constexpr double kRoundOff = 1.0e-12;
  const double travel = last.position[0] - first.position[0];
  ASSERT_GT(std::abs(travel), 0.1);  // the effort did move the arm
  EXPECT_NEAR(last.external_work, kEffort * travel, kRoundOff * std::abs(kEffort * travel));
  // Energy identity (T6): kinetic + potential + dissipated + numerical - external stays at its initial value, to
  // the Newton tolerance (relative to the energies passed around) over the run's steps.
  const double books = last.total() + last.dissipated + last.numerical_dissipation - last.external_work;
  const double throughput = std::abs(first.total()) + last.kinetic + std::abs(last.external_work);
  constexpr double kBooksTolerance = 1.0e-9;  // 200 steps at tol 1e-12 with room for round-off
  EXPECT_NEAR(books, first.total(), kBooksTolerance * throughput);
}

TEST(DriveSetpoint, FollowsAFirstOrderLag) {
  ModelSpec spec = TiltedPendulum();
  TimeFunctionSpec hold;  // the drive's own law: hold the initial angle
  hold.value = kAngle;
  spec.joints[0].effects[0].drives.push_back(hold);
  spec.solver.adaptive = true;  // the lag is exact over any step: varying steps must not change it
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  constexpr double kSetpoint = 1.2, kTimeConstant = 0.3;
  simulation.SetSetpoint(0, kSetpoint, kTimeConstant);
  double worst = 0;
  simulation.Integrate(model.solver().t_end, [&](const OutputSample&) {
    const State& state = simulation.state();
    const double expected = kSetpoint + (kAngle - kSetpoint) * std::exp(-state.t / kTimeConstant);
    worst = std::max(worst, std::abs(state.q[0] - expected));
  });
  // Closed form: tau q' + q = s from q(0), q = s + (q(0) - s) exp(-t / tau), met by the drive constraint at each
  // step's end to the Newton tolerance (constraint rows, relative to 1 rad), with round-off in exp over 2 s.
  constexpr double kLagTolerance = 1.0e-10;
  EXPECT_LT(worst, kLagTolerance);
  EXPECT_GT(std::abs(simulation.state().q[0] - kAngle), 0.5);  // it moved to the set-point, not the law
}

TEST(Commands, BadCommandsNameTheVariable) {
  const Model model = BuildModel(TiltedPendulum());
  Simulation simulation(model);
  EXPECT_THROW(
      {
        try {
          simulation.SetSetpoint(0, 1.0, 0.1);
        } catch (const ConfigError& e) {
          EXPECT_STREQ(e.what(), "set-point for joint variable 'pivot', which has no drive; expected a set-point "
                                 "for a driven variable");
          throw;
        }
      },
      ConfigError);
  EXPECT_THROW(
      {
        try {
          simulation.SetEffort(0, std::nan(""));
        } catch (const ConfigError& e) {
          EXPECT_STREQ(e.what(), "effort for joint variable 'pivot': nan is not a finite number");
          throw;
        }
      },
      ConfigError);
  EXPECT_THROW(simulation.SetEffort(1, 0.0), ConfigError);
}

}  // namespace commands_test
}  // namespace flexmbd
