// Applied loads (include/flexmbd/elements/applied_load.hpp) on one node, with hand-built step contexts: the
// generalised force against closed forms, and the exactness of the work of a dead force at an offset.

#include <gtest/gtest.h>

#include <vector>

#include "flexmbd/elements/applied_load.hpp"
#include "flexmbd/math/so3.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace applied_load_test {

// Short sums of rounded products of O(1..10) factors: a few ulp of the largest term.
constexpr double kRoundOff = 1.0e-13;

LoadSpec Load(LoadSpec::Kind kind, LoadSpec::Frame frame, const Vec3& vector) {
  LoadSpec spec;
  spec.body = "body";
  spec.kind = kind;
  spec.frame = frame;
  spec.vector = vector;
  return spec;
}

// A one-node context: dynamic from `start` by `increment`, or static at start moved by it.
struct OneNode {
  std::vector<NodeStep> nodes;
  StepContext ctx;

  OneNode(const NodeState& start, const Vec6& increment, AnalysisMode mode) {
    nodes.push_back(MakeNodeStep(start, increment, mode));
    ctx.mode = mode;
    ctx.t_i = 1.0;
    ctx.t_f = mode == AnalysisMode::kDynamic ? 1.2 : 1.0;
    ctx.h = mode == AnalysisMode::kDynamic ? 0.2 : 1.0;
    ctx.nodes = &nodes;
  }
};

Vec6 Residual(const AppliedLoad& load, const StepContext& ctx) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6), magnitude = Eigen::VectorXd::Zero(6);
  load.AddResidual(ctx, r, magnitude);
  return r;
}

TEST(AppliedLoad, DeadForceWorkEqualsForceTimesPointDisplacement) {
  // Reference: exact change of the point: dx + R_f p - R_i p, so -r . (dx, theta) = F . (change of the point)
  // for any finite rotation (up to 2 rad here); AddStepWork reports the same.
  test::Random random(901);
  const Vec3 F(1.0, -2.0, 3.0), p(0.3, -0.4, 0.25);
  const AppliedLoad load(0, 0, Load(LoadSpec::Kind::kForce, LoadSpec::Frame::kWorld, F), p);
  for (int trial = 0; trial < 10; ++trial) {
    Vec6 increment;
    increment << random.Vector(0.2), random.Uniform(0.0, 2.0) * random.UnitVector();
    const OneNode step(random.Node(1.0, 1.0), increment, AnalysisMode::kDynamic);
    const NodeStep& n = step.nodes[0];
    const double work = -Residual(load, step.ctx).dot(increment);
    const double exact = F.dot(n.x_f + n.R_f * p - n.x_i - n.R_i * p);
    EXPECT_NEAR(work, exact, kRoundOff) << "trial " << trial;
    StepWork step_work;
    load.AddStepWork(step.ctx, &step_work);
    EXPECT_NEAR(step_work.external, exact, kRoundOff) << "trial " << trial;
  }
}

TEST(AppliedLoad, WorldMomentWorkEqualsMomentTimesWorldRotation) {
  // Reference: a rotation by phi about a fixed world axis a (R_f = Rot(a, phi) R_i, theta = phi R_i^T a) is
  // worked on by a world moment M exactly M . a phi.
  test::Random random(902);
  const Vec3 M(0.5, 1.5, -2.0);
  const AppliedLoad load(0, 0, Load(LoadSpec::Kind::kMoment, LoadSpec::Frame::kWorld, M), Vec3::Zero());
  for (int trial = 0; trial < 10; ++trial) {
    const NodeState start = random.Node(1.0, 1.0);
    const Vec3 a = random.UnitVector();
    const double phi = random.Uniform(-2.0, 2.0);
    Vec6 increment;
    increment << Vec3::Zero(), phi * start.R.transpose() * a;
    const OneNode step(start, increment, AnalysisMode::kDynamic);
    EXPECT_NEAR(-Residual(load, step.ctx).dot(increment), M.dot(a) * phi, kRoundOff) << "trial " << trial;
  }
}

TEST(AppliedLoad, DeadForceStaticResidualIsForceAndMomentAboutNode) {
  // Reference: r = -(F, p x (R^T F)) at the iterate, scaled by the load factor and the scale law at t_f.
  test::Random random(903);
  LoadSpec spec = Load(LoadSpec::Kind::kForce, LoadSpec::Frame::kWorld, Vec3(1.0, -2.0, 3.0));
  spec.scale.kind = TimeFunctionSpec::Kind::kLinearRamp;
  spec.scale.offset = 0.0;
  spec.scale.value = 2.0;
  spec.scale.duration = 4.0;  // scale 0.5 at t = 1
  const Vec3 p(0.3, -0.4, 0.25);
  const AppliedLoad load(0, 0, spec, p);
  OneNode step(random.Node(1.0, 1.0), Vec6::Zero(), AnalysisMode::kStatic);
  step.ctx.load_factor = 0.6;
  const Vec3 F = 0.6 * 0.5 * spec.vector;
  const Mat3 R = step.nodes[0].R_f;
  Vec6 expected;
  expected << -F, -p.cross(R.transpose() * F);
  EXPECT_LT((Residual(load, step.ctx) - expected).norm(), kRoundOff);
}

TEST(AppliedLoad, FollowerForceStaticResidualTurnsWithBody) {
  // Reference: a body-frame force f at p: r = -(R f, p x f).
  test::Random random(904);
  const Vec3 f(0.7, 0.2, -1.1), p(0.3, -0.4, 0.25);
  const AppliedLoad load(0, 0, Load(LoadSpec::Kind::kForce, LoadSpec::Frame::kBody, f), p);
  const OneNode step(random.Node(1.0, 1.0), Vec6::Zero(), AnalysisMode::kStatic);
  Vec6 expected;
  expected << -(step.nodes[0].R_f * f), -p.cross(f);
  EXPECT_LT((Residual(load, step.ctx) - expected).norm(), kRoundOff);
}

TEST(AppliedLoad, DynamicScaleIsTakenAtMidStep) {
  // Reference: header: "scaled by a time function taken at mid-step": linear ramp 0 -> 1 over [0, 2] s gives
  // 0.55 at t = (1.0 + 1.2)/2 for a body moment (no rotation dependence).
  LoadSpec spec = Load(LoadSpec::Kind::kMoment, LoadSpec::Frame::kBody, Vec3(0.0, 0.0, 2.0));
  spec.scale.kind = TimeFunctionSpec::Kind::kLinearRamp;
  spec.scale.offset = 0.0;
  spec.scale.value = 1.0;
  spec.scale.duration = 2.0;
  const AppliedLoad load(0, 0, spec, Vec3::Zero());
  test::Random random(905);
  Vec6 increment;
  increment << random.Vector(0.1), random.Vector(0.3);
  const OneNode step(random.Node(1.0, 1.0), increment, AnalysisMode::kDynamic);
  Vec6 expected;
  expected << Vec3::Zero(), -0.55 * spec.vector;
  EXPECT_LT((Residual(load, step.ctx) - expected).norm(), kRoundOff);
}

// The load stiffness of every kind of load, in a step (asked for with geometric_stiffness) and in statics,
// against central differences of the residual along the increments as the solver applies them. Step 1e-6 on
// loads and offsets of order 1: difference error ~1e-10; 1e-7 of the largest entry, the bar of every analytic
// tangent, and a wrong term shows at order 1.
TEST(AppliedLoad, LoadStiffnessIsExactForEveryKindAndAnalysis) {
  constexpr double kStep = 1.0e-6, kTolerance = 1.0e-7;
  test::Random random(31);
  for (AnalysisMode mode : {AnalysisMode::kDynamic, AnalysisMode::kStatic}) {
    for (LoadSpec::Kind kind : {LoadSpec::Kind::kForce, LoadSpec::Kind::kMoment}) {
      for (LoadSpec::Frame frame : {LoadSpec::Frame::kWorld, LoadSpec::Frame::kBody}) {
        const AppliedLoad load(0, 0, Load(kind, frame, random.Vector(3.0)), random.Vector(1.0));
        Vec6 increment;
        increment << random.Vector(0.1), random.Vector(0.8);
        OneNode at(random.Node(1.0, 1.0), increment, mode);
        at.ctx.geometric_stiffness = true;
        Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, 6), fd(6, 6);
        load.AddTangent(at.ctx, J);
        const NodeStep base = at.nodes[0];
        for (int k = 0; k < 6; ++k) {
          at.nodes[0] = PerturbNodeStep(base, kStep * Vec6::Unit(k), mode);
          const Vec6 plus = Residual(load, at.ctx);
          at.nodes[0] = PerturbNodeStep(base, -kStep * Vec6::Unit(k), mode);
          fd.col(k) = (plus - Residual(load, at.ctx)) / (2 * kStep);
        }
        EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), kTolerance * std::max(1.0, test::MaxAbs(fd)))
            << "mode " << static_cast<int>(mode) << " kind " << static_cast<int>(kind) << " frame "
            << static_cast<int>(frame) << "\nanalytic\n" << J << "\ndifference\n" << fd;
      }
    }
  }
}

}  // namespace applied_load_test
}  // namespace flexmbd
