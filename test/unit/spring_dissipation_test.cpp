// The energy-decaying scheme's dissipation in a spring (docs/theory.md, (T6)): its tangent against central
// differences, and the work identity -Q dq = V_f - V_i + k alpha (dq - dq_lagged) dq.

#include <gtest/gtest.h>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "tangent_test_models.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace spring_dissipation_test {

constexpr double kAlpha = 0.07;
constexpr double kStep = 0.01;

struct SpringCase {
  Model model = BuildModel(test::WorldRevoluteModel());
  State start;
  Eigen::VectorXd unknowns;
  const Element* spring = nullptr;
  SpringCase() {
    test::Random random(7);
    start = test::PerturbedState(model, &random);
    start.h_prev = 0.8 * kStep;
    start.dq_prev = Eigen::VectorXd::Constant(model.num_variables(), 0.004);
    unknowns = test::RandomUnknowns(model, &random);
    for (const auto& element : model.elements()) {
      if (dynamic_cast<const VariableSpring*>(element.get())) spring = element.get();
    }
  }
  double Residual(StepContextBuilder* builder, const Eigen::VectorXd& u) const {
    builder->set_variable_dissipation({kAlpha});
    const std::vector<NodeSchemeCoefficients> nodes(model.num_nodes());
    Eigen::VectorXd r = Eigen::VectorXd::Zero(1), m = Eigen::VectorXd::Zero(1);
    spring->AddResidual(builder->Dynamic(start, u, kStep, nodes), r, m);
    return r[0];
  }
};

TEST(SpringDissipation, TangentMatchesCentralDifferences) {
  SpringCase c;
  ASSERT_NE(c.spring, nullptr);
  StepContextBuilder builder(c.model);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(1, 1);
  c.Residual(&builder, c.unknowns);
  c.spring->AddTangent(builder.context(), J);
  // The residual is linear in the increment, so central differences are exact up to round-off.
  constexpr double kDelta = 1.0e-6, kTolerance = 1.0e-8;
  const int u = c.spring->unknowns()[0];
  Eigen::VectorXd plus = c.unknowns, minus = c.unknowns;
  plus[u] += kDelta;
  minus[u] -= kDelta;
  const double fd = (c.Residual(&builder, plus) - c.Residual(&builder, minus)) / (2 * kDelta);
  EXPECT_NEAR(J(0, 0), fd, kTolerance * std::abs(fd));
}

TEST(SpringDissipation, WorkIsEnergyChangePlusDissipation) {
  SpringCase c;
  StepContextBuilder builder(c.model);
  const double force = c.Residual(&builder, c.unknowns);
  const VariableStep& q = builder.context().variables->at(0);
  const double k = 3.5, rest = 0.1;  // WorldRevoluteModel's spring
  const double dq = q.q_f - q.q_i;
  const double energy_change = 0.5 * k * ((q.q_f - rest) * (q.q_f - rest) - (q.q_i - rest) * (q.q_i - rest));
  StepWork work;
  c.spring->AddStepWork(builder.context(), &work);
  // An algebraic identity: round-off only.
  constexpr double kIdentity = 1.0e-13;
  EXPECT_NEAR(force * dq, energy_change + work.numerical, kIdentity);
  EXPECT_NEAR(q.dq_lagged, kStep / (0.8 * kStep) * 0.004, kIdentity);
}

}  // namespace spring_dissipation_test
}  // namespace flexmbd
