// Analytic element tangents (AddTangent) against central finite differences of the element residuals
// (AddResidual) w.r.t. the element's local unknowns. The residual depends on the trial unknowns through the
// StepContext, so each difference perturbs one global unknown and rebuilds the context with the builder.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/effects/variable_effects.hpp"
#include "flexmbd/elements/applied_load.hpp"
#include "flexmbd/elements/rigid_body.hpp"
#include "flexmbd/joints/joint.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "tangent_test_models.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace element_tangent_test {

// Step size of the dynamic tests [s].
constexpr double kStepSize = 0.01;
// Central-difference step on unknowns of size 0.01..10.
constexpr double kFiniteDifferenceStep = 1.0e-6;
// Relative to the largest tangent entry. Central differences: truncation ~ step^2 |r'''| ~ 1e-12, round-off
// ~ 1e-16 |r| / step ~ 1e-10. Every tangent here is analytic (the joints' geometric stiffness included), so
// 1e-7 leaves a margin of 1e3 over the difference error, while a missing or wrong term fails by orders.
constexpr double kTangentTolerance = 1.0e-7;

using ContextAt = std::function<const StepContext&(const Eigen::VectorXd& unknowns)>;

using test::LocalResidual;
using test::LocalTangent;

Eigen::MatrixXd FiniteDifferenceTangent(const Element& e, const ContextAt& context_at, const Eigen::VectorXd& u) {
  Eigen::MatrixXd J(e.num_local(), e.num_local());
  for (int j = 0; j < e.num_local(); ++j) {
    Eigen::VectorXd plus = u, minus = u;
    plus[e.unknowns()[j]] += kFiniteDifferenceStep;
    minus[e.unknowns()[j]] -= kFiniteDifferenceStep;
    const Eigen::VectorXd r_plus = LocalResidual(e, context_at(plus));
    const Eigen::VectorXd r_minus = LocalResidual(e, context_at(minus));
    J.col(j) = (r_plus - r_minus) / (2.0 * kFiniteDifferenceStep);
  }
  return J;
}

// Compares the analytic tangent at u with finite differences; names the worst entry on failure.
void ExpectTangentMatchesFiniteDifference(const Element& e, const ContextAt& context_at, const Eigen::VectorXd& u,
                                          const std::string& what) {
  const Eigen::MatrixXd fd = FiniteDifferenceTangent(e, context_at, u);
  const Eigen::MatrixXd J = LocalTangent(e, context_at(u));
  const double scale = std::max(1.0, test::MaxAbs(fd));
  Eigen::Index row = 0, col = 0;
  const double worst = (J - fd).cwiseAbs().maxCoeff(&row, &col);
  EXPECT_LT(worst, kTangentTolerance * scale)
      << what << ": entry (" << row << ", " << col << ") analytic " << J(row, col) << " finite difference "
      << fd(row, col) << ", scale " << scale;
}

template <typename ElementType>
std::vector<const ElementType*> ElementsOf(const Model& model) {
  std::vector<const ElementType*> found;
  for (const auto& e : model.elements()) {
    if (const auto* typed = dynamic_cast<const ElementType*>(e.get())) found.push_back(typed);
  }
  return found;
}

// Sets chosen parts of a random start state and trial unknowns (e.g. a stop's gap and mode); none by default.
using Placement = std::function<void(State* start, Eigen::VectorXd* unknowns)>;

// Checks every element of the type in dynamic mode at random trial points, for alpha 0 and 0.1.
template <typename ElementType>
void ExpectDynamicTangents(const Model& model, unsigned seed, const Placement& place = {}) {
  const std::vector<const ElementType*> elements = ElementsOf<ElementType>(model);
  ASSERT_FALSE(elements.empty());
  test::Random random(seed);
  StepContextBuilder builder(model);
  builder.set_geometric_stiffness(true);
  for (double alpha : {0.0, 0.1}) {
    const std::vector<NodeSchemeCoefficients> coefficients(model.num_nodes(), NodeSchemeCoefficients{alpha, alpha});
    for (int trial = 0; trial < 3; ++trial) {
      State start = test::PerturbedState(model, &random);
      Eigen::VectorXd u = test::RandomUnknowns(model, &random);
      if (place) place(&start, &u);
      const ContextAt context_at = [&](const Eigen::VectorXd& unknowns) -> const StepContext& {
        return builder.Dynamic(start, unknowns, kStepSize, coefficients);
      };
      for (const ElementType* e : elements) {
        ExpectTangentMatchesFiniteDifference(*e, context_at, u,
                                             "alpha " + std::to_string(alpha) + " trial " + std::to_string(trial));
      }
    }
  }
}

// Checks every element of the type in static mode at random iterates. The node increments are zero, as in the
// static solver, which linearises at the iterate: static node steps take the rotation increment as a further
// rotation R Exp(d) of the moved pose (T = I), exact at zero increment. Variable increments and multipliers are
// random.
template <typename ElementType>
void ExpectStaticTangents(const Model& model, unsigned seed, const Placement& place = {}) {
  const std::vector<const ElementType*> elements = ElementsOf<ElementType>(model);
  ASSERT_FALSE(elements.empty());
  test::Random random(seed);
  StepContextBuilder builder(model);
  builder.set_geometric_stiffness(true);
  for (int trial = 0; trial < 3; ++trial) {
    State iterate = test::PerturbedState(model, &random);
    Eigen::VectorXd u = test::RandomUnknowns(model, &random);
    u.head(6 * model.num_nodes()).setZero();
    if (place) place(&iterate, &u);
    const double load_factor = random.Uniform(0.2, 1.0);
    const ContextAt context_at = [&](const Eigen::VectorXd& unknowns) -> const StepContext& {
      return builder.Static(iterate, unknowns, iterate.t, load_factor);
    };
    for (const ElementType* e : elements) {
      ExpectTangentMatchesFiniteDifference(*e, context_at, u, "static trial " + std::to_string(trial));
    }
  }
}

TEST(ElementTangent, RigidBodyDynamicMatchesFiniteDifference) {
  // Reference: central differences of m (v_f - v_i)/h - m g and (Exp(theta) J w_f - J w_i)/h, w_f from (T3).
  ExpectDynamicTangents<RigidBody>(BuildModel(test::WorldRevoluteModel()), 201);
}

TEST(ElementTangent, VariableSpringDynamicMatchesFiniteDifference) {
  // Reference: central differences of k (q_m - rest): k/2 per unit dq.
  ExpectDynamicTangents<VariableSpring>(BuildModel(test::WorldRevoluteModel()), 202);
}

TEST(ElementTangent, VariableDamperDynamicMatchesFiniteDifference) {
  // Reference: central differences of c (q_f - q_i)/h.
  ExpectDynamicTangents<VariableDamper>(BuildModel(test::WorldRevoluteModel()), 203);
}

TEST(ElementTangent, VariableDriveDynamicMatchesFiniteDifference) {
  // Reference: central differences of (lambda, q_f - f(t_f)).
  ExpectDynamicTangents<VariableDrive>(BuildModel(test::WorldRevoluteModel()), 204);
}

TEST(ElementTangent, WorldRevoluteJointDynamicMatchesFiniteDifference) {
  // Reference: central differences of (G^T lambda, phi_f) with the geometric stiffness on.
  ExpectDynamicTangents<Joint>(BuildModel(test::WorldRevoluteModel()), 205);
}

TEST(ElementTangent, AppliedDeadForceAtOffsetStaticMatchesFiniteDifference) {
  // Reference: central differences of -(F, p x R^T F) at the iterate. (The dynamic tangent documents that it
  // omits the load-rotation terms, so only statics is checked.)
  ExpectStaticTangents<AppliedLoad>(BuildModel(test::WorldRevoluteModel()), 206);
}

TEST(ElementTangent, WorldRevoluteJointStaticMatchesFiniteDifference) {
  // Reference: central differences of (G^T lambda, phi) at the iterate, geometric stiffness on.
  ExpectStaticTangents<Joint>(BuildModel(test::WorldRevoluteModel()), 207);
}

TEST(ElementTangent, RigidBodyStaticMatchesFiniteDifference) {
  // Reference: the static residual is the constant weight -lf m g: zero tangent.
  ExpectStaticTangents<RigidBody>(BuildModel(test::WorldRevoluteModel()), 208);
}

TEST(ElementTangent, VariableEffectsStaticMatchFiniteDifference) {
  // Reference: central differences of k (q - rest) (slope k), of the damper's zero static force, and of the drive.
  const Model model = BuildModel(test::WorldRevoluteModel());
  ExpectStaticTangents<VariableSpring>(model, 209);
  ExpectStaticTangents<VariableDamper>(model, 210);
  ExpectStaticTangents<VariableDrive>(model, 211);
}

TEST(ElementTangent, StaticHoldMatchesFiniteDifference) {
  // Reference: central differences of (lambda, q - q0) in statics and of (0, lambda) in time steps. The hold
  // replaces WorldRevoluteModel's drive (both on one variable are refused) and needs a static analysis.
  ModelSpec spec = test::WorldRevoluteModel();
  spec.joints[0].effects[0].drives.clear();
  spec.joints[0].effects[0].static_hold = true;
  spec.solver.static_first = true;
  const Model model = BuildModel(spec);
  ExpectStaticTangents<VariableHold>(model, 212);
  ExpectDynamicTangents<VariableHold>(model, 213);
}

// The hinge of WorldRevoluteModel with one lower stop at 0.25 rad (its initial angle is 0.3 rad).
constexpr double kStopAngle = 0.25;
Model ModelWithStop(StopSpec stop) {
  ModelSpec spec = test::WorldRevoluteModel();
  stop.name = "lower";
  stop.side = StopSpec::Side::kLower;
  stop.limit = kStopAngle;
  spec.joints[0].effects[0].stops = {stop};
  return BuildModel(spec);
}

// Places the hinge's angle at the stop angle + `offset` at the start of the step, moving by `increment` at the
// step's mean rate, with the stop in `mode` and, for an elastic stop, a remembered approach speed of 0.5 m/s.
Placement AtStop(const Model& model, double offset, double increment, int mode) {
  return [&model, offset, increment, mode](State* start, Eigen::VectorXd* u) {
    start->q[0] = kStopAngle + offset;
    start->qdot[0] = increment / kStepSize;
    start->effects[0] = EffectState{mode, 0.5, 0.0, 0};
    (*u)[model.variable_unknown(0)] = increment;
  };
}

TEST(ElementTangent, RigidStopMatchesFiniteDifference) {
  // Reference: central differences of (-s rho lambda, g_f - g_i) in contact, (0, lambda) open (C2a).
  StopSpec rigid;
  rigid.radius = 0.15;
  const Model model = ModelWithStop(rigid);
  for (int mode : {JointStop::kOpen, JointStop::kContact}) {
    ExpectDynamicTangents<RigidStop>(model, 212, AtStop(model, -0.01, -0.02, mode));
    ExpectStaticTangents<RigidStop>(model, 213, AtStop(model, -0.01, -0.02, mode));
  }
}

// A Hertz stop of 1e4 N/m^1.5 at radius 0.3 m with restitution 0.6.
StopSpec HertzStop() {
  StopSpec elastic;
  elastic.radius = 0.3;
  elastic.kind = StopSpec::Kind::kElastic;
  elastic.stiffness = 1.0e4;
  elastic.restitution = 0.6;
  return elastic;
}

TEST(ElementTangent, ElasticStopMatchesFiniteDifference) {
  // Reference: central differences of -s rho DG (1 + chi (a_f - a_i)/h) (C2b) for a Hertz stop, in a step that
  // stays in contact, one that closes the gap and one that opens it (the discrete gradient over signed
  // approaches), and of -s rho DG in statics. The approaches stay >= 6e-4 m from 0, far beyond the difference
  // step (3e-7 m), so no difference straddles the kink of V at a = 0.
  const Model model = ModelWithStop(HertzStop());
  ExpectDynamicTangents<ElasticStop>(model, 214, AtStop(model, -0.03, -0.02, JointStop::kContact));
  ExpectDynamicTangents<ElasticStop>(model, 215, AtStop(model, 0.01, -0.03, JointStop::kOpen));
  ExpectDynamicTangents<ElasticStop>(model, 216, AtStop(model, -0.01, 0.012, JointStop::kContact));
  ExpectStaticTangents<ElasticStop>(model, 217, AtStop(model, -0.03, -0.02, JointStop::kContact));
}

TEST(ElementTangent, HertzStopAtFirstTouchTakesItsTouchStiffnessInStaticsAndTheLawsApproach) {
  // Reference: the Hertz law F = k a^1.5 (k 1e4 N/m^1.5, radius 0.3 m). Its V'' = 1.5 k a^0.5 vanishes at first touch,
  // where a static iteration takes the law's stiffness at 1e-3 times the model's size instead (docs/theory.md, "Static
  // increments"); an open gap has none, a deep approach its own. An increment dq into the stop from first touch
  // predicts the force K rho |dq|, and the joint goes to the approach (F / k)^(2/3) of it. Exact formulas: to 1e-14.
  constexpr double kFormula = 1.0e-14, kRadius = 0.3, kK = 1.0e4;
  const Model model = ModelWithStop(HertzStop());
  const ElasticStop& stop = *ElementsOf<ElasticStop>(model).at(0);
  const double touch = 1.5 * kK * std::sqrt(1.0e-3 * model.length_scale());
  EXPECT_NEAR(stop.StaticStiffness(0.0), touch, kFormula * touch);
  EXPECT_NEAR(stop.StaticStiffness(1.0), 1.5 * kK, kFormula * kK);
  EXPECT_EQ(stop.StaticStiffness(-1.0e-9), 0.0);
  const double dq = -0.01, approach = std::pow(touch * kRadius * -dq / kK, 2.0 / 3.0);
  EXPECT_NEAR(stop.StaticPosition(kStopAngle, dq), kStopAngle - approach / kRadius, kFormula);
  // Moving off the stop, or from an open gap, the joint takes the increment as it is.
  EXPECT_EQ(stop.StaticPosition(kStopAngle, 0.01), kStopAngle + 0.01);
  EXPECT_EQ(stop.StaticPosition(kStopAngle + 0.1, -0.2), kStopAngle + 0.1 - 0.2);
}

TEST(ElementTangent, ElasticStopEndPointPartsMatchFiniteDifference) {
  // Reference: central differences of -s rho V'(a) (1 + chi a_dot_f) at the end point (eigen-analysis), in the
  // configuration (stiffness V''(a) (1 + chi a_dot_f)) and in the end rate (damping V'(a) chi): a Hertz stop in
  // contact 9e-3 m deep, closing at 0.09 m/s, remembered approach speed 0.5 m/s. The stiffness was once the discrete
  // gradient's derivative in the end alone, V''/2, which halved a stop's stiffness in every eigen-analysis, and the
  // damping was missing.
  const Model model = ModelWithStop(HertzStop());
  State start = model.initial_state();
  start.q[0] = kStopAngle - 0.03;
  start.effects[0] = EffectState{JointStop::kContact, 0.5, 0.0, 0};
  const ElasticStop& stop = *ElementsOf<ElasticStop>(model).at(0);
  ASSERT_TRUE(stop.HasRateParts(AnalysisMode::kEndPoint));
  StepContextBuilder builder(model);
  auto context_at = [&](const Eigen::VectorXd& u) -> const StepContext& {
    const StepContext& ctx = builder.EndPoint(start, u, start.t, 1.0e-3);
    builder.variables()[0].qdot_f = -0.3;
    return ctx;
  };
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(model.num_unknowns());
  ExpectTangentMatchesFiniteDifference(stop, context_at, u, "end point");
  const test::RateParts parts = test::LocalRateParts(stop, context_at(u));
  const Eigen::MatrixXd damping = test::RateDifferences(stop, context_at(u), false, kFiniteDifferenceStep);
  EXPECT_GT(test::MaxAbs(damping), 0.0);
  EXPECT_LT(test::MaxAbs(parts.D - damping), kTangentTolerance * test::MaxAbs(damping)) << parts.D << "\n" << damping;
  EXPECT_EQ(test::MaxAbs(parts.M), 0.0);
}

TEST(ElementTangent, LinearElasticStopMatchesFiniteDifferenceInStaticsOpenAndInContact) {
  // Reference: central differences of -s rho k a (a > 0; zero for an open gap). A static tangent took the linear
  // law's slope k also for an open gap, so a hinge with stops far away was stiffened against a residual without
  // them (the wing with aileron's free flap between +-5 deg stops: no equilibrium found).
  StopSpec linear;
  linear.radius = 0.3;
  linear.kind = StopSpec::Kind::kElastic;
  linear.law = StopSpec::Law::kLinear;
  linear.stiffness = 1.0e4;
  linear.restitution = 1.0;
  const Model model = ModelWithStop(linear);
  ExpectStaticTangents<ElasticStop>(model, 218, AtStop(model, 0.05, 0.01, JointStop::kOpen));
  ExpectStaticTangents<ElasticStop>(model, 219, AtStop(model, -0.03, -0.02, JointStop::kContact));
}

TEST(ElementInterface, ResidualAndTangentTogetherEqualSeparateCalls) {
  // Reference: AddResidualAndTangent (used by the assembly) must add exactly what AddResidual and AddTangent add,
  // and with J null exactly the residual; for every element of both models, dynamic and static.
  // Same arithmetic in the same order is expected, but allow a few ulp of each entry for a shared evaluation.
  constexpr double kSameArithmetic = 1.0e-14;
  test::Random random(240);
  for (const ModelSpec& spec : {test::WorldRevoluteModel(), test::SingleJointModel(JointType::kPlanar, false)}) {
    const Model model = BuildModel(spec);
    StepContextBuilder builder(model);
    builder.set_geometric_stiffness(true);
    const State start = test::PerturbedState(model, &random);
    Eigen::VectorXd u = test::RandomUnknowns(model, &random);
    const std::vector<NodeSchemeCoefficients> coefficients(model.num_nodes(), NodeSchemeCoefficients{0.1, 0.1});
    for (bool dynamic : {true, false}) {
      if (!dynamic) u.head(6 * model.num_nodes()).setZero();
      const StepContext& ctx =
          dynamic ? builder.Dynamic(start, u, kStepSize, coefficients) : builder.Static(start, u, start.t, 0.7);
      for (const auto& e : model.elements()) {
        const int m = e->num_local();
        const Eigen::VectorXd r = LocalResidual(*e, ctx);
        Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, m);
        e->AddTangent(ctx, J);
        Eigen::VectorXd r_both = Eigen::VectorXd::Zero(m), mag_both = r_both, r_only = r_both, mag_only = r_both;
        Eigen::VectorXd mag = Eigen::VectorXd::Zero(m), scratch = Eigen::VectorXd::Zero(m);
        e->AddResidual(ctx, scratch, mag);
        Eigen::MatrixXd J_both = Eigen::MatrixXd::Zero(m, m);
        Eigen::Ref<Eigen::MatrixXd> J_ref = J_both;
        e->AddResidualAndTangent(ctx, r_both, mag_both, &J_ref);
        e->AddResidualAndTangent(ctx, r_only, mag_only, nullptr);
        const double scale = 1.0 + test::MaxAbs(r) + test::MaxAbs(J);
        EXPECT_LT(test::MaxAbs(r_both - r), kSameArithmetic * scale) << model.source();
        EXPECT_LT(test::MaxAbs(r_only - r), kSameArithmetic * scale) << model.source();
        EXPECT_LT(test::MaxAbs(mag_both - mag), kSameArithmetic * scale) << model.source();
        EXPECT_LT(test::MaxAbs(J_both - J), kSameArithmetic * scale) << model.source();
      }
    }
  }
}

class JointTangent : public ::testing::TestWithParam<test::JointCase> {};

TEST_P(JointTangent, DynamicMatchesFiniteDifference) {
  // Reference: central differences of (G^T lambda, phi_f) in dynamic mode, geometric stiffness on.
  const Model model = BuildModel(test::SingleJointModel(GetParam().type, GetParam().world_parent));
  ExpectDynamicTangents<Joint>(model, 300 + static_cast<unsigned>(GetParam().type));
}

TEST_P(JointTangent, StaticMatchesFiniteDifference) {
  // Reference: central differences of (G^T lambda, phi) in static mode, geometric stiffness on.
  const Model model = BuildModel(test::SingleJointModel(GetParam().type, GetParam().world_parent));
  ExpectStaticTangents<Joint>(model, 400 + static_cast<unsigned>(GetParam().type));
}

TEST_P(JointTangent, RigidBodiesDynamicMatchFiniteDifference) {
  // Reference: central differences of the inertial residuals of the bodies of the same model.
  const Model model = BuildModel(test::SingleJointModel(GetParam().type, GetParam().world_parent));
  ExpectDynamicTangents<RigidBody>(model, 500 + static_cast<unsigned>(GetParam().type));
}

INSTANTIATE_TEST_SUITE_P(AllTypes, JointTangent, ::testing::ValuesIn(test::AllJointCases()), test::JointCaseName);

}  // namespace element_tangent_test
}  // namespace flexmbd
