// NodeStep construction (include/flexmbd/elements/element.hpp): configuration from an increment, the scheme
// relation (theory eq. (T3)) behind the end velocities, and finite-difference perturbations.

#include <gtest/gtest.h>

#include "flexmbd/elements/element.hpp"
#include "flexmbd/math/so3.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace node_step_test {

// Each checked quantity is a short sum of rounded O(1..100) terms: a few ulp of its size.
constexpr double kRoundOff = 1.0e-13;

Vec6 RandomIncrement(test::Random* random) {
  Vec6 d;
  d << random->Vector(0.1), random->Vector(0.5);
  return d;
}

TEST(NodeStep, DynamicStepMovesFromStartByIncrement) {
  // Reference: x_f = x + dx, R_f = R Exp(theta), start values kept, S and T of theta (docs of MakeNodeStep).
  test::Random random(801);
  const NodeState start = random.Node(1.0, 1.0);
  const Vec6 d = RandomIncrement(&random);
  const NodeStep n = MakeNodeStep(start, d, AnalysisMode::kDynamic);
  EXPECT_LT((n.x_i - start.x).norm(), kRoundOff);
  EXPECT_LT((n.x_f - start.x - d.head<3>()).norm(), kRoundOff);
  EXPECT_LT((n.R_i - start.R).norm(), kRoundOff);
  EXPECT_LT((n.R_f - start.R * Exp(d.tail<3>())).norm(), kRoundOff);
  EXPECT_LT((n.dx - d.head<3>()).norm(), kRoundOff);
  EXPECT_LT((n.theta - d.tail<3>()).norm(), kRoundOff);
  EXPECT_LT((n.S - SecantOperator(d.tail<3>())).norm(), kRoundOff);
  EXPECT_LT((n.T - RightJacobian(d.tail<3>())).norm(), kRoundOff);
}

TEST(NodeStep, StaticStepStandsStillAtMovedPose) {
  // Reference: in statics the start is moved to the end: i = f = (x + dx, R Exp(theta)), zero increments,
  // S = T = I.
  test::Random random(802);
  const NodeState start = random.Node(1.0, 1.0);
  const Vec6 d = RandomIncrement(&random);
  const NodeStep n = MakeNodeStep(start, d, AnalysisMode::kStatic);
  EXPECT_LT((n.x_i - start.x - d.head<3>()).norm(), kRoundOff);
  EXPECT_LT((n.x_f - n.x_i).norm(), kRoundOff);
  EXPECT_LT((n.R_f - start.R * Exp(d.tail<3>())).norm(), kRoundOff);
  EXPECT_LT((n.R_i - n.R_f).norm(), kRoundOff);
  EXPECT_EQ(n.dx.norm(), 0.0);
  EXPECT_EQ(n.theta.norm(), 0.0);
  EXPECT_TRUE(n.S.isIdentity(0.0));
  EXPECT_TRUE(n.T.isIdentity(0.0));
}

TEST(NodeStep, EndVelocitiesSatisfySchemeRelation) {
  // Reference: theory eq. (T3) as documented on NodeSchemeCoefficients:
  //   x_f - x_i = h [(v_i + v_f)/2 + alpha (v_f - v_i - h a_prev)], the same for theta, w and alpha_prev,
  // with d v_f / d dx = 1/(h (1/2 + alpha)); alpha = 0 (energy preserving) and alpha > 0, different per part.
  test::Random random(803);
  const double h = 0.01;
  for (const NodeSchemeCoefficients c : {NodeSchemeCoefficients{0.0, 0.0}, NodeSchemeCoefficients{0.1, 0.25}}) {
    NodeState start = random.Node(1.0, 2.0);
    start.a_prev = random.Vector(10.0);
    start.alpha_prev = random.Vector(10.0);
    NodeStep n = MakeNodeStep(start, RandomIncrement(&random), AnalysisMode::kDynamic);
    SetNodeStepVelocities(start, h, c, &n);
    const double at = c.alpha_translation, ar = c.alpha_rotation;
    const Vec3 translation = h * (0.5 * (n.v_i + n.v_f) + at * (n.v_f - n.v_i - h * start.a_prev));
    const Vec3 rotation = h * (0.5 * (n.w_i + n.w_f) + ar * (n.w_f - n.w_i - h * start.alpha_prev));
    EXPECT_LT((n.v_i - start.v).norm(), kRoundOff);
    EXPECT_LT((n.w_i - start.w).norm(), kRoundOff);
    EXPECT_LT((translation - n.dx).norm(), kRoundOff);
    EXPECT_LT((rotation - n.theta).norm(), kRoundOff);
    EXPECT_NEAR(n.dvf_ddx * h * (0.5 + at), 1.0, kRoundOff);
    EXPECT_NEAR(n.dwf_dtheta * h * (0.5 + ar), 1.0, kRoundOff);
  }
}

TEST(NodeStep, DynamicPerturbationAddsToTheIncrement) {
  // Reference: PerturbNodeStep(n, d) in dynamics = MakeNodeStep(start, increment + d): the FD tangents
  // perturb the unknown itself.
  test::Random random(804);
  const NodeState start = random.Node(1.0, 1.0);
  const Vec6 increment = RandomIncrement(&random), d = RandomIncrement(&random);
  const NodeStep moved =
      PerturbNodeStep(MakeNodeStep(start, increment, AnalysisMode::kDynamic), d, AnalysisMode::kDynamic);
  const NodeStep expected = MakeNodeStep(start, increment + d, AnalysisMode::kDynamic);
  EXPECT_LT((moved.x_i - expected.x_i).norm(), kRoundOff);
  EXPECT_LT((moved.x_f - expected.x_f).norm(), kRoundOff);
  EXPECT_LT((moved.R_i - expected.R_i).norm(), kRoundOff);
  EXPECT_LT((moved.R_f - expected.R_f).norm(), kRoundOff);
  EXPECT_LT((moved.theta - expected.theta).norm(), kRoundOff);
  EXPECT_LT((moved.S - expected.S).norm(), kRoundOff);
  EXPECT_LT((moved.T - expected.T).norm(), kRoundOff);
}

TEST(NodeStep, StaticPerturbationMovesTheCurrentPose) {
  // Reference: in statics the perturbation is a further increment of the current pose:
  // x + d_x, R Exp(d_theta).
  test::Random random(805);
  const NodeState start = random.Node(1.0, 1.0);
  const Vec6 increment = RandomIncrement(&random), d = RandomIncrement(&random);
  const NodeStep at = MakeNodeStep(start, increment, AnalysisMode::kStatic);
  const NodeStep moved = PerturbNodeStep(at, d, AnalysisMode::kStatic);
  EXPECT_LT((moved.x_f - at.x_f - d.head<3>()).norm(), kRoundOff);
  EXPECT_LT((moved.R_f - at.R_f * Exp(d.tail<3>())).norm(), kRoundOff);
  EXPECT_LT((moved.R_i - moved.R_f).norm(), kRoundOff);
}

TEST(StepContext, MidRateIsHalfInDynamicsAndOneInStatics) {
  // Reference: d(mid-step value)/d(increment): 1/2 for the midpoint, 1 for the end value (exact).
  StepContext ctx;
  ctx.mode = AnalysisMode::kDynamic;
  EXPECT_EQ(ctx.mid_rate(), 0.5);
  ctx.mode = AnalysisMode::kStatic;
  EXPECT_EQ(ctx.mid_rate(), 1.0);
}

}  // namespace node_step_test
}  // namespace flexmbd
