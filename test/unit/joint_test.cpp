// The joint element (include/flexmbd/joints/joint.hpp): its constraint rows vanish exactly on poses built from
// the relative-motion description, and its constraint forces G^T lambda are an exact discrete gradient, so
// their work over any step equals lambda . (phi_f - phi_i).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/joints/joint.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "tangent_test_models.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace joint_test {

// Poses are composed from O(1) rotations and offsets: the constraint rows are round-off, a few ulp of O(1).
constexpr double kPoseRoundOff = 1.0e-14;
// The work identity sums ~20 products of O(10) forces and O(0.1) increments: a few ulp of the sum of their sizes.
constexpr double kWorkIdentity = 1.0e-13;

// The single-joint model with the child placed at relative motion q.
ModelSpec JointAt(const test::JointCase& c, const Eigen::VectorXd& q) {
  ModelSpec spec = test::SingleJointModel(c.type, c.world_parent);
  JointSpec& joint = spec.joints[0];
  joint.initial_position.assign(q.data(), q.data() + q.size());
  BodySpec& child = spec.bodies.back();
  if (c.world_parent) {
    test::PlaceChild(Vec3::Zero(), Mat3::Identity(), joint, &child);
  } else {
    test::PlaceChild(spec.bodies[0].p_WB, spec.bodies[0].R_WB, joint, &child);
  }
  return spec;
}

class JointElement : public ::testing::TestWithParam<test::JointCase> {};

TEST_P(JointElement, ConstraintVanishesOnPosesFromRelativeMotion) {
  // Reference: p_WJc = p_WJp + R_WJp t(q), R_WJc = R_WJp Rel(q) (joint_kinematics.hpp) makes both rows zero,
  // for large relative motions.
  test::Random random(700 + static_cast<unsigned>(GetParam().type));
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd q = random.VectorX(NumJointVariables(GetParam().type), 3.0);
    const Model model = BuildModel(JointAt(GetParam(), q));
    StepContextBuilder builder(model);
    const Eigen::VectorXd phi = model.joints()[0]->ConstraintValues(builder.AtState(model.initial_state()));
    EXPECT_LT(test::MaxAbs(phi), kPoseRoundOff) << "q " << q.transpose();
  }
}

TEST_P(JointElement, ModelRejectsChildDisplacedOffTheJoint) {
  // Reference: a rigid translation of the child by 1e-3 m in a generic direction leaves the joint's motion
  // space, so the initial-pose check (tolerance 1e-8) throws ConfigError.
  test::Random random(710 + static_cast<unsigned>(GetParam().type));
  ModelSpec spec = JointAt(GetParam(), Eigen::VectorXd::Zero(NumJointVariables(GetParam().type)));
  spec.bodies.back().p_WB += 1.0e-3 * random.UnitVector();
  EXPECT_THROW(BuildModel(spec), ConfigError);
}

TEST_P(JointElement, ConstraintForceWorkEqualsMultipliersTimesConstraintChange) {
  // Reference: exact discrete gradient: sum_k (G^T lambda)_k xi_k = lambda . (phi_f - phi_i) for any step xi,
  // phi_i from the start state and phi_f the residual's constraint rows; large random steps.
  const Model model = BuildModel(test::SingleJointModel(GetParam().type, GetParam().world_parent));
  const Joint& joint = *model.joints()[0];
  test::Random random(720 + static_cast<unsigned>(GetParam().type));
  StepContextBuilder dynamic(model), at_start(model);
  const std::vector<NodeSchemeCoefficients> coefficients(model.num_nodes());
  for (int trial = 0; trial < 5; ++trial) {
    const State start = test::PerturbedState(model, &random);
    const Eigen::VectorXd u = test::RandomUnknowns(model, &random);
    const Eigen::VectorXd phi_i = joint.ConstraintValues(at_start.AtState(start));
    const StepContext& ctx = dynamic.Dynamic(start, u, 0.01, coefficients);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(joint.num_local()), magnitude = r;
    joint.AddResidual(ctx, r, magnitude);
    const int n_increments = joint.num_local() - joint.num_constraints();
    double work = 0.0, size = 0.0;
    for (int k = 0; k < n_increments; ++k) {
      work += r[k] * u[joint.unknowns()[k]];
      size += std::abs(r[k] * u[joint.unknowns()[k]]);
    }
    const Eigen::VectorXd lambda =
        u.tail(model.num_multipliers()).segment(joint.first_multiplier(), joint.num_constraints());
    const Eigen::VectorXd phi_f = r.tail(joint.num_constraints());
    EXPECT_NEAR(work, lambda.dot(phi_f - phi_i), kWorkIdentity * (1.0 + size)) << "trial " << trial;
  }
}

TEST_P(JointElement, VariableForcesAreTheVariableResidualRows) {
  // Reference: VariableForces = G_q^T lambda, the joint's residual rows of its own variables (same expression).
  const Model model = BuildModel(test::SingleJointModel(GetParam().type, GetParam().world_parent));
  const Joint& joint = *model.joints()[0];
  test::Random random(730 + static_cast<unsigned>(GetParam().type));
  StepContextBuilder builder(model);
  const std::vector<NodeSchemeCoefficients> coefficients(model.num_nodes());
  const State start = test::PerturbedState(model, &random);
  const StepContext& ctx = builder.Dynamic(start, test::RandomUnknowns(model, &random), 0.01, coefficients);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(joint.num_local()), magnitude = r;
  joint.AddResidual(ctx, r, magnitude);
  const int n_var = joint.num_variables();
  const Eigen::VectorXd rows = r.segment(joint.num_local() - joint.num_constraints() - n_var, n_var);
  EXPECT_LT(test::MaxAbs(joint.VariableForces(ctx) - rows), kPoseRoundOff * (1.0 + test::MaxAbs(rows)));
}

INSTANTIATE_TEST_SUITE_P(AllTypes, JointElement, ::testing::ValuesIn(test::AllJointCases()), test::JointCaseName);

}  // namespace joint_test
}  // namespace flexmbd
