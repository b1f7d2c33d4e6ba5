// Sparse assembly and KLU solve (include/flexmbd/solver/sparse_system.hpp) against a dense reference assembled
// here from the element residuals and tangents.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "tangent_test_models.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace sparse_system_test {

constexpr double kStepSize = 0.01;
// The sparse and dense sums add the same terms, possibly in another order: a few ulp of the largest term.
constexpr double kAssembly = 1.0e-14;
// A backward-stable LU solve leaves |J dx + r| within a small multiple of eps (|J| |dx| + |r|).
constexpr double kBackwardError = 1.0e-12;

// The world-revolute model with a second body hanging from it on a universal joint.
ModelSpec TwoBodyModel() {
  ModelSpec spec = test::WorldRevoluteModel();
  BodySpec tip = test::Body("tip", 0.7, Vec3(0.05, 0.2, -0.1));
  JointSpec joint = test::SkewedJoint("wrist", JointType::kUniversal, "link", "tip");
  test::PlaceChild(spec.bodies[0].p_WB, spec.bodies[0].R_WB, joint, &tip);
  spec.bodies.push_back(tip);
  spec.joints.push_back(joint);
  return spec;
}

struct Dense {
  Eigen::VectorXd residual, magnitude;
  Eigen::MatrixXd tangent;
};

// Element-by-element assembly into dense storage: the reference for SparseSystem.
Dense AssembleDense(const Model& model, const StepContext& ctx) {
  const int n = model.num_unknowns();
  Dense d{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), Eigen::MatrixXd::Zero(n, n)};
  for (const auto& e : model.elements()) {
    const int m = e->num_local();
    Eigen::VectorXd r = Eigen::VectorXd::Zero(m), mag = Eigen::VectorXd::Zero(m);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, m);
    e->AddResidual(ctx, r, mag);
    AddSchemeTangent(*e, ctx, J);
    const std::vector<int>& u = e->unknowns();
    for (int i = 0; i < m; ++i) {
      d.residual[u[i]] += r[i];
      d.magnitude[u[i]] += mag[i];
      for (int j = 0; j < m; ++j) d.tangent(u[i], u[j]) += J(i, j);
    }
  }
  return d;
}

class SparseSystemTest : public ::testing::Test {
 protected:
  SparseSystemTest() : model_(BuildModel(TwoBodyModel())), builder_(model_), random_(601) {
    builder_.set_geometric_stiffness(true);
    coefficients_.assign(model_.num_nodes(), NodeSchemeCoefficients{0.1, 0.1});
  }

  // A dynamic context at a random start and random trial unknowns (start_ is kept alive for it).
  const StepContext& RandomContext() {
    start_ = test::PerturbedState(model_, &random_);
    const Eigen::VectorXd u = test::RandomUnknowns(model_, &random_);
    return builder_.Dynamic(start_, u, kStepSize, coefficients_);
  }

  // Checks J dx = -r for the dense reference of the same context, and dx against a dense LU solve.
  void ExpectSolvesDenseSystem(const Dense& dense, const Eigen::VectorXd& dx) {
    ASSERT_EQ(dx.size(), model_.num_unknowns());
    const double backward =
        (dense.tangent * dx + dense.residual).norm() / (dense.tangent.norm() * dx.norm() + dense.residual.norm());
    EXPECT_LT(backward, kBackwardError);
    // Forward error of two backward-stable solves: bounded by ~cond(J) eps each; 10x margin.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense.tangent);
    const double condition = svd.singularValues()(0) / svd.singularValues().tail(1)(0);
    const Eigen::VectorXd reference = dense.tangent.fullPivLu().solve(-dense.residual);
    const double forward_tolerance = 10.0 * condition * std::numeric_limits<double>::epsilon();
    EXPECT_LT((dx - reference).norm(), forward_tolerance * reference.norm()) << "condition " << condition;
  }

  Model model_;
  StepContextBuilder builder_;
  test::Random random_;
  std::vector<NodeSchemeCoefficients> coefficients_;
  State start_;
};

TEST_F(SparseSystemTest, PatternHoldsExactlyTheCoupledEntries) {
  // Reference: the union over elements of (unknowns x unknowns) pairs.
  std::set<std::pair<int, int>> entries;
  for (const auto& e : model_.elements()) {
    for (int i : e->unknowns()) {
      for (int j : e->unknowns()) entries.insert({i, j});
    }
  }
  SparseSystem system(model_);
  EXPECT_EQ(system.num_nonzeros(), static_cast<int>(entries.size()));
}

TEST_F(SparseSystemTest, ResidualIsSumOfElementResiduals) {
  // Reference: scatter-add of each element's local residual and magnitude by its unknowns.
  SparseSystem system(model_);
  const StepContext& ctx = RandomContext();
  const Dense dense = AssembleDense(model_, ctx);
  system.Assemble(ctx, false);
  EXPECT_LT((system.residual() - dense.residual).cwiseAbs().maxCoeff(),
            kAssembly * (1.0 + dense.magnitude.cwiseAbs().maxCoeff()));
  EXPECT_LT((system.magnitude() - dense.magnitude).cwiseAbs().maxCoeff(),
            kAssembly * (1.0 + dense.magnitude.cwiseAbs().maxCoeff()));
  system.Assemble(ctx, true);
  EXPECT_LT((system.residual() - dense.residual).cwiseAbs().maxCoeff(),
            kAssembly * (1.0 + dense.magnitude.cwiseAbs().maxCoeff()));
}

TEST_F(SparseSystemTest, SolveMatchesDenseSolve) {
  // Reference: J dx = -r with J, r assembled densely from the element tangents and residuals; dense LU.
  SparseSystem system(model_);
  const StepContext& ctx = RandomContext();
  const Dense dense = AssembleDense(model_, ctx);
  system.Assemble(ctx, true);
  Eigen::VectorXd dx;
  ASSERT_TRUE(system.Solve(&dx));
  ExpectSolvesDenseSystem(dense, dx);
}

TEST_F(SparseSystemTest, RefactorisationAtNewPointsSolvesEachSystem) {
  // Reference: as above, at successive trial points (the second and later solves reuse the symbolic analysis
  // and refactorise numerically).
  SparseSystem system(model_);
  for (int iteration = 0; iteration < 4; ++iteration) {
    const StepContext& ctx = RandomContext();
    const Dense dense = AssembleDense(model_, ctx);
    system.Assemble(ctx, true);
    Eigen::VectorXd dx;
    ASSERT_TRUE(system.Solve(&dx)) << "iteration " << iteration;
    ExpectSolvesDenseSystem(dense, dx);
  }
}

ModelSpec FreeBodySpec() {
  ModelSpec spec;
  spec.bodies.push_back(test::Body("free", 1.0, Vec3::Zero()));
  return spec;
}

// A free body under gravity at rest, and its system: in statics its tangent is zero.
struct FreeBody {
  Model model = BuildModel(FreeBodySpec());
  StepContextBuilder builder{model};
  SparseSystem system{model};
  State state = model.initial_state();
};

TEST(SparseSystem, SolveReportsSingularMatrix) {
  // Reference: a free body in statics has a zero tangent (its only residual is the constant weight):
  // Solve must return false, not a non-finite dx.
  FreeBody body;
  body.system.Assemble(body.builder.AtState(body.state), true);
  Eigen::VectorXd dx;
  EXPECT_FALSE(body.system.Solve(&dx));
}

TEST(SparseSystem, NoFactorisationIsKeptForASingularMatrix) {
  // Reference: a free body. Its dynamic tangent (inertia) factorises; its static tangent is zero, so the
  // refactorisation in the dynamic pivot order meets a zero pivot and fresh pivoting fails too. The factors left
  // are partial: they may not serve a later solve that reuses a factorisation, and the dynamic system solves
  // again afterwards.
  FreeBody body;
  const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(body.model.num_unknowns());
  const std::vector<NodeSchemeCoefficients> coefficients(body.model.num_nodes());
  Eigen::VectorXd dx;
  body.system.Assemble(body.builder.Dynamic(body.state, at_rest, kStepSize, coefficients), true);
  ASSERT_TRUE(body.system.Solve(&dx));
  body.system.Assemble(body.builder.AtState(body.state), true);
  EXPECT_FALSE(body.system.Solve(&dx));
  EXPECT_FALSE(body.system.has_factorisation());
  EXPECT_FALSE(body.system.Solve(&dx, false));
  const StepContext& ctx = body.builder.Dynamic(body.state, at_rest, kStepSize, coefficients);
  const Dense dense = AssembleDense(body.model, ctx);
  body.system.Assemble(ctx, true);
  ASSERT_TRUE(body.system.Solve(&dx));
  EXPECT_LT((dense.tangent * dx + dense.residual).norm(), kBackwardError * dense.residual.norm());
}

}  // namespace sparse_system_test
}  // namespace flexmbd
