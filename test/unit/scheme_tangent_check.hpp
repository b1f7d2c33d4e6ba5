#pragma once
// The check shared by the aerodynamic elements' tangent tests: the whole scheme tangent of a mid-step
// (energy-decaying) step against central differences of the residual, near a given start.

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
  auto context = [&](const Eigen::VectorXd& u) -> const StepContext& { return builder.Dynamic(start, u, h, trapezoidal); };
  const Eigen::VectorXd u = SomeIncrements(model);
  const Eigen::MatrixXd expected = UnknownDifferences(element, u, context, step);
  const Eigen::MatrixXd actual = LocalTangent(element, context(u));
  EXPECT_LT(MaxAbs(actual - expected), tolerance * MaxAbs(expected)) << "analytic\n"
                                                                      << actual << "\ndifferences\n"
                                                                      << expected;
}

}  // namespace test
}  // namespace flexmbd
