#pragma once
// The checks shared by the aerodynamic elements' tangent tests, against central differences of the residual: the
// whole scheme tangent of a mid-step (energy-decaying) step near a given start, and the end point's stiffness and
// rate parts.

#include <gtest/gtest.h>

#include <vector>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace test {

// Increments of every kinematic unknown drawn in [-1e-3, 1e-3] (seed 7), zero elsewhere: a point near the start
// at which a tangent is compared with differences.
inline Eigen::VectorXd SomeIncrements(const Model& model) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.num_unknowns());
  Random random(7);
  u.head(model.num_kinematic()) = random.VectorX(model.num_kinematic(), 1.0e-3);
  return u;
}

// Expects the scheme tangent of `element` in a step of 1 ms from `start` (trapezoidal coefficients), at
// SomeIncrements, to equal central differences of its residual (steps `step`) within `tolerance` times their
// largest entry.
inline void ExpectMidStepTangentMatchesDifferences(const Model& model, const Element& element, const State& start,
                                                   double step, double tolerance) {
  StepContextBuilder builder(model);
  const std::vector<NodeSchemeCoefficients> trapezoidal(model.num_nodes());
  const double h = 1.0e-3;
  auto context = [&](const Eigen::VectorXd& u) -> const StepContext& {
    return builder.Dynamic(start, u, h, trapezoidal);
  };
  const Eigen::VectorXd u = SomeIncrements(model);
  const Eigen::MatrixXd expected = UnknownDifferences(element, u, context, step);
  const Eigen::MatrixXd actual = LocalTangent(element, context(u));
  EXPECT_LT(MaxAbs(actual - expected), tolerance * MaxAbs(expected)) << "analytic\n"
                                                                      << actual << "\ndifferences\n"
                                                                      << expected;
}

// Expects the end-point stiffness (Element::AddTangent) and rate parts (D, M) of `element` at time `t`, about the
// iterate itself, to equal differences of its residual (steps `step` in the unknowns, `rate_step` in the rates)
// within `tolerance` times their largest entry. The nodes' end rates are random (seed 7): velocities of scale
// `speed` [m/s], angular velocities 2 rad/s, accelerations 10 m/s^2, angular accelerations 30 rad/s^2. About the
// iterate the increment is zero, where a rotation increment turns a node's frame by itself (about a nonzero one
// theta it turns it by T(theta) dtheta, which the end point's tangent does not hold).
inline void ExpectEndPointPartsMatchDifferences(const Model& model, const Element& element, const State& start,
                                                double t, double speed, double step, double rate_step,
                                                double tolerance) {
  StepContextBuilder builder(model);
  auto context = [&](const Eigen::VectorXd& u) -> const StepContext& {
    StepContext& ctx = builder.EndPoint(start, u, t, 1.0e-3);
    Random random(7);
    for (NodeStep& n : builder.nodes()) {
      n.v_f = random.Vector(speed);
      n.w_f = random.Vector(2.0);
      n.vdot_f = random.Vector(10.0);
      n.wdot_f = random.Vector(30.0);
    }
    return ctx;
  };
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(model.num_unknowns());
  const StepContext& ctx = context(u);
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(element.num_local(), element.num_local());
  element.AddTangent(ctx, stiffness);
  const Eigen::MatrixXd expected = UnknownDifferences(element, u, context, step);
  EXPECT_LT(MaxAbs(stiffness - expected), tolerance * MaxAbs(expected)) << "analytic\n"
                                                                         << stiffness << "\ndifferences\n"
                                                                         << expected;
  const RateParts parts = LocalRateParts(element, context(u));
  for (bool accelerations : {false, true}) {
    const Eigen::MatrixXd differences = RateDifferences(element, context(u), accelerations, rate_step);
    const Eigen::MatrixXd& analytic = accelerations ? parts.M : parts.D;
    EXPECT_LT(MaxAbs(analytic - differences), tolerance * MaxAbs(differences))
        << (accelerations ? "M" : "D") << "\nanalytic\n" << analytic << "\ndifferences\n" << differences;
  }
}

}  // namespace test
}  // namespace flexmbd
