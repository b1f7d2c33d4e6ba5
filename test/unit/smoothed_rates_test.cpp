// The rates an eigen-analysis at a time of a run linearises about (WithSmoothedRates, docs/theory.md (E10)): from
// the mean rates of the last three steps of unequal size, a node on a screw motion (a constant body twist: a
// steady rotation is one) gets its velocity and angular velocity exactly, and a joint variable moving at a rate
// linear in time its rate, whatever the end rates the scheme left.

#include <gtest/gtest.h>

#include "flexmbd/math/so3.hpp"
#include "flexmbd/solver/smoothed_rates.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {
namespace smoothed_rates_test {

const Vec3 kBodyVelocity(0.3, 2.0, -0.1);  // nu [m/s]
const Vec3 kBodySpin(0.2, -0.4, 3.0);      // omega [rad/s]
const Mat3 kStartRotation = Exp(Vec3(0.5, -0.2, 0.9));
const Vec3 kStartPosition(1.0, -2.0, 0.5);

// The screw motion at time t: R = R0 Exp(t omega), x = x0 + R0 t J(t omega) nu, J the right Jacobian's transpose.
// The joint variable q = 0.5 + 1.5 t - 2 t^2, its rate linear in t.
State ScrewStateAt(double t) {
  State state;
  state.t = t;
  state.nodes.resize(1);
  NodeState& node = state.nodes[0];
  node.R = kStartRotation * Exp(t * kBodySpin);
  node.x = kStartPosition + kStartRotation * (t * RightJacobian(t * kBodySpin).transpose() * kBodyVelocity);
  // End rates as a scheme would leave them, off by an alternating mode.
  node.v = node.R * kBodyVelocity + Vec3(0.05, -0.02, 0.01);
  node.w = kBodySpin - Vec3(0.01, 0.0, 0.03);
  state.q = Eigen::VectorXd::Constant(1, 0.5 + 1.5 * t - 2.0 * t * t);
  state.qdot = Eigen::VectorXd::Constant(1, 1.5 - 4.0 * t + 0.1);
  return state;
}

// The state after steps of the given sizes from t = 0, each booked as an accepted step.
State AfterSteps(const std::vector<double>& steps) {
  State state = ScrewStateAt(0.0);
  for (double h : steps) {
    State end = ScrewStateAt(state.t + h);
    RecordStepHistory(state, h, &end);
    state = std::move(end);
  }
  return state;
}

// Round-off of the rotation maps over a few steps of 0.1 rad.
constexpr double kRoundOff = 1.0e-12;

TEST(SmoothedRates, ScrewMotionGetsItsRatesExactlyFromUnequalSteps) {
  const State end = AfterSteps({0.04, 0.05, 0.03, 0.02});
  const State smoothed = WithSmoothedRates(end);
  EXPECT_LT((smoothed.nodes[0].v - end.nodes[0].R * kBodyVelocity).norm(), kRoundOff * kBodyVelocity.norm());
  EXPECT_LT((smoothed.nodes[0].w - kBodySpin).norm(), kRoundOff * kBodySpin.norm());
  // The mean rates of a linear rate are its midpoint values, and a parabola through them holds a line.
  EXPECT_NEAR(smoothed.qdot[0], 1.5 - 4.0 * end.t, kRoundOff);
  // Positions are the scheme's.
  EXPECT_EQ(smoothed.nodes[0].x, end.nodes[0].x);
  EXPECT_EQ(smoothed.q, end.q);
}

TEST(SmoothedRates, FewerThanThreeStepsKeepTheEndRates) {
  const State end = AfterSteps({0.04, 0.05});
  const State smoothed = WithSmoothedRates(end);
  EXPECT_EQ(smoothed.nodes[0].v, end.nodes[0].v);
  EXPECT_EQ(smoothed.nodes[0].w, end.nodes[0].w);
  EXPECT_EQ(smoothed.qdot, end.qdot);
}

}  // namespace smoothed_rates_test
}  // namespace flexmbd
