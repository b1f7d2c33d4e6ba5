// The rate parts of element tangents (Element::AddRateParts) against central differences of the residual in the
// end rates and accelerations, and their combination with a scheme's coefficients (AddSchemeRateTerms).

#include <gtest/gtest.h>

#include <vector>

#include "flexmbd/effects/variable_effects.hpp"
#include "flexmbd/elements/rigid_body.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace tangent_parts_test {

// Rates and accelerations of order 1: central differences of residuals at most quadratic in them (the
// gyroscopic w x J w) are exact to round-off, ~1e-16 |r| / 1e-6 = 1e-10 of the largest entry.
constexpr double kRateStep = 1.0e-6;
constexpr double kRateTolerance = 1.0e-8;

void ExpectPartsMatchDifferences(const Element& e, const StepContext& ctx, const char* what) {
  const test::RateParts parts = test::LocalRateParts(e, ctx);
  for (bool accelerations : {false, true}) {
    const Eigen::MatrixXd expected = test::RateDifferences(e, ctx, accelerations, kRateStep);
    const Eigen::MatrixXd& actual = accelerations ? parts.M : parts.D;
    EXPECT_LT(test::MaxAbs(actual - expected), kRateTolerance * std::max(1.0, test::MaxAbs(expected)))
        << what << (accelerations ? " M" : " D") << "\nanalytic\n" << actual << "\ndifference\n" << expected;
  }
}

struct OneBody {
  RigidBody body{0, 0, 2.5, (Mat3() << 0.4, 0.05, -0.02, 0.05, 0.3, 0.01, -0.02, 0.01, 0.2).finished()};
  std::vector<NodeStep> nodes;
  StepContext ctx;

  OneBody(AnalysisMode mode, test::Random* random) {
    Vec6 increment;
    increment << random->Vector(0.05), random->Vector(0.3);
    NodeStep s = MakeNodeStep(random->Node(1.0, 1.0), increment, mode);
    s.v_f = random->Vector(1.0);
    s.w_f = random->Vector(2.0);
    s.vdot_f = random->Vector(1.0);
    s.wdot_f = random->Vector(1.0);
    nodes = {s};
    ctx.mode = mode;
    ctx.h = 0.01;
    ctx.nodes = &nodes;
  }
};

TEST(TangentParts, RigidBodyRatePartsAreTheResidualsRateDerivatives) {
  // Reference: differences of m (v_f - v_i)/h and (Exp(theta) J w_f - J w_i)/h in a dynamic step (D = m/h,
  // Exp(theta) J / h; M = 0), and of m vdot_f and J wdot_f + w_f x J w_f at the end point (D the gyroscopic
  // block, M = diag(m, J)); nothing in statics.
  test::Random random(61);
  for (AnalysisMode mode : {AnalysisMode::kDynamic, AnalysisMode::kEndPoint}) {
    for (int trial = 0; trial < 3; ++trial) {
      const OneBody one(mode, &random);
      ASSERT_TRUE(one.body.HasRateParts(mode));
      ExpectPartsMatchDifferences(one.body, one.ctx, mode == AnalysisMode::kDynamic ? "dynamic" : "end point");
    }
  }
  EXPECT_FALSE(RigidBody(0, 0, 1.0, Mat3::Identity()).HasRateParts(AnalysisMode::kStatic));
}

TEST(TangentParts, DamperRatePartIsItsCoefficientAtTheEndPoint) {
  // Reference: the end-point force c qdot_f has D = c; the dynamic step's c (q_f - q_i)/h reads no end rate.
  const VariableDamper damper(0, 0, 3.5);
  std::vector<VariableStep> variables(1);
  variables[0].qdot_f = 0.7;
  StepContext ctx;
  ctx.mode = AnalysisMode::kEndPoint;
  ctx.variables = &variables;
  ASSERT_TRUE(damper.HasRateParts(AnalysisMode::kEndPoint));
  EXPECT_FALSE(damper.HasRateParts(AnalysisMode::kDynamic));
  ExpectPartsMatchDifferences(damper, ctx, "damper");
  EXPECT_NEAR(test::LocalRateParts(damper, ctx).D(0, 0), 3.5, 1.0e-15);
}

TEST(TangentParts, SchemeCombinesThePartsColumnByColumn) {
  // Reference: K + D diag(c_v) + M diag(c_a) with the translation, rotation and acceleration coefficients of the
  // node, assembled by hand from the parts. Same arithmetic, so equal to round-off of the largest entry.
  test::Random random(62);
  OneBody one(AnalysisMode::kEndPoint, &random);
  one.nodes[0].dvf_ddx = 30.0;
  one.nodes[0].dwf_dtheta = 20.0;
  one.nodes[0].dacc = 900.0;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6);
  one.body.AddTangent(one.ctx, K);
  const test::RateParts parts = test::LocalRateParts(one.body, one.ctx);
  Eigen::MatrixXd expected = K;
  for (int j = 0; j < 6; ++j) expected.col(j) += (j < 3 ? 30.0 : 20.0) * parts.D.col(j) + 900.0 * parts.M.col(j);
  const Eigen::MatrixXd combined = test::LocalTangent(one.body, one.ctx);
  EXPECT_LT(test::MaxAbs(combined - expected), 1.0e-14 * test::MaxAbs(expected));
}

}  // namespace tangent_parts_test
}  // namespace flexmbd
