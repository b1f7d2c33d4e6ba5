// The beam element's analytic forces and tangents (BeamStrainField, BeamElement) against references that
// share no code with them: forces against forward-mode automatic differentiation of an independently written
// strain energy, tangents against central differences of those forces, for every analysis the element serves,
// at random large-rotation states of linear, quadratic and cubic elements.

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "flexmbd/elements/beam_element.hpp"
#include "flexmbd/math/rotation_vector_calculus.hpp"
#include "flexmbd/math/so3_generic.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace beam_tangent_test {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// Central-difference step [m or rad]: truncation step^2 |f'''| ~ 1e-12 and round-off eps |f| / step ~ 1e-10,
// both relative to the largest tangent entry of these well-conditioned sections.
constexpr double kStep = 1.0e-6;
// The bar for analytic tangents: 1e-7 relative to the largest entry, a margin of 1e3 over the
// difference error above, while a missing or wrong term shows at 1e-3 or more.
constexpr double kTangentTolerance = 1.0e-7;
// Forces against automatic differentiation: both exact up to round-off of sums of ~100 terms.
constexpr double kForceTolerance = 1.0e-12;

// ---- the rotation-vector derivatives -------------------------------------------------------------------

// Angles on both sides of the series switch (2 rad) and from tiny to near pi.
const std::vector<double> kAngles = {0.0, 1.0e-7, 1.0e-3, 0.3, 1.2, 1.99, 2.01, 2.8, 3.1};
// Central differences of T (entries <= 1) with step 1e-6: error below 1e-10.
constexpr double kCalculusTolerance = 1.0e-9;

TEST(RotationVectorCalculus, MapsMatchSo3) {
  test::Random random(11);
  for (double angle : kAngles) {
    const Vec3 psi = angle * random.UnitVector();
    const RotationVectorCalculus c(psi);
    // Both are sums of the same few terms; 1e-14 is a few eps of entries <= 1.
    EXPECT_LT((c.exp() - Exp(psi)).cwiseAbs().maxCoeff(), 1e-14) << angle;
    EXPECT_LT((c.tangent() - RightJacobian(psi)).cwiseAbs().maxCoeff(), 1e-14) << angle;
    EXPECT_LT((c.tangent() * c.inverse_tangent() - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-13) << angle;
  }
}

TEST(RotationVectorCalculus, DerivativesMatchFiniteDifferences) {
  test::Random random(12);
  for (double angle : kAngles) {
    const Vec3 psi = angle * random.UnitVector();
    const Vec3 d1 = random.UnitVector(), d2 = random.UnitVector();
    const RotationVectorCalculus c(psi);
    auto T = [&](const Vec3& p) { return RotationVectorCalculus(p).tangent(); };
    auto Tinv = [&](const Vec3& p) { return RotationVectorCalculus(p).inverse_tangent(); };
    auto DT = [&](const Vec3& p) { return RotationVectorCalculus(p).TangentDerivative(d1); };
    const Mat3 fd_T = (T(psi + kStep * d1) - T(psi - kStep * d1)) / (2 * kStep);
    const Mat3 fd_Tinv = (Tinv(psi + kStep * d1) - Tinv(psi - kStep * d1)) / (2 * kStep);
    const Mat3 fd_DT = (DT(psi + kStep * d2) - DT(psi - kStep * d2)) / (2 * kStep);
    EXPECT_LT((c.TangentDerivative(d1) - fd_T).cwiseAbs().maxCoeff(), kCalculusTolerance) << angle;
    EXPECT_LT((c.InverseTangentDerivative(d1) - fd_Tinv).cwiseAbs().maxCoeff(), kCalculusTolerance) << angle;
    EXPECT_LT((c.TangentSecondDerivative(d1, d2) - fd_DT).cwiseAbs().maxCoeff(), kCalculusTolerance) << angle;
    // The contracted form against the contraction of the full second derivative: same terms, round-off only.
    const Vec3 m = random.Vector(2.0), v = random.Vector(2.0);
    const Mat3 form = c.TangentSecondDerivativeForm(m, v);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double contracted = m.dot(c.TangentSecondDerivative(Vec3::Unit(i), Vec3::Unit(j)) * v);
        EXPECT_NEAR(form(i, j), contracted, 1e-13) << angle;
      }
    }
    // The applied forms against DT[e_j] v and DT[e_j]^T v: the same terms regrouped, round-off only.
    for (int j = 0; j < 3; ++j) {
      const Mat3 DT = c.TangentDerivative(Vec3::Unit(j));
      EXPECT_LT((c.TangentDerivativeApplied(v).col(j) - DT * v).cwiseAbs().maxCoeff(), 1e-13) << angle;
      EXPECT_LT((c.TransposedTangentDerivativeApplied(v).col(j) - DT.transpose() * v).cwiseAbs().maxCoeff(), 1e-13)
          << angle;
    }
  }
}

// ---- reference strain energy by automatic differentiation ----------------------------------------------

using AutoDiff = Eigen::AutoDiffScalar<Eigen::VectorXd>;
template <class T>
using V3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using M3 = Eigen::Matrix<T, 3, 3>;

// Rotation vector of a rotation by less than pi/2 (enough for the states below), for any scalar.
template <class T>
V3<T> LogOf(const M3<T>& R) {
  const V3<T> a(0.5 * (R(2, 1) - R(1, 2)), 0.5 * (R(0, 2) - R(2, 0)), 0.5 * (R(1, 0) - R(0, 1)));
  const T s = sqrt(T(a.squaredNorm()) + 1e-300);
  return (asin(s) / s) * a;
}

// Strain energy (B1)-(B3) of an element with nodes at x_k + u_k, R_k Exp(phi_k), p = (u_k, phi_k).
template <class T>
T ReferenceEnergy(const std::vector<Vec3>& x, const std::vector<Mat3>& R, const Eigen::Matrix<T, Eigen::Dynamic, 1>& p,
                  double length, const Mat6& C) {
  const int n = static_cast<int>(x.size()), order = n - 1, r = order / 2;
  std::vector<V3<T>> xs(n);
  std::vector<M3<T>> Rs(n), psi_nodes(n);
  std::vector<V3<T>> psi(n);
  for (int k = 0; k < n; ++k) {
    xs[k] = x[k].cast<T>() + p.template segment<3>(6 * k);
    Rs[k] = R[k].cast<T>() * so3::ExpOf<T>(V3<T>(p.template segment<3>(6 * k + 3)));
  }
  for (int k = 0; k < n; ++k) psi[k] = k == r ? V3<T>::Zero().eval() : LogOf<T>(M3<T>(Rs[r].transpose() * Rs[k]));
  std::vector<double> points, weights;
  if (order == 1) points = {0.0}, weights = {2.0};
  if (order == 2) points = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}, weights = {1.0, 1.0};
  if (order == 3) points = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, weights = {5 / 9.0, 8 / 9.0, 5 / 9.0};
  T energy = T(0.0);
  for (size_t g = 0; g < points.size(); ++g) {
    // Lagrange polynomials and their s-derivatives at the point, written out from the definition.
    std::vector<double> N(n, 1.0), dN(n, 0.0);
    for (int k = 0; k < n; ++k) {
      const double xk = -1.0 + 2.0 * k / order;
      for (int j = 0; j < n; ++j) {
        if (j == k) continue;
        const double xj = -1.0 + 2.0 * j / order;
        N[k] *= (points[g] - xj) / (xk - xj);
        double term = 2.0 / length / (xk - xj);
        for (int m = 0; m < n; ++m) {
          const double xm = -1.0 + 2.0 * m / order;
          if (m != k && m != j) term *= (points[g] - xm) / (xk - xm);
        }
        dN[k] += term;
      }
    }
    V3<T> psi_g = V3<T>::Zero(), dpsi = V3<T>::Zero(), dx = V3<T>::Zero();
    for (int k = 0; k < n; ++k) {
      psi_g += N[k] * psi[k];
      dpsi += dN[k] * psi[k];
      dx += dN[k] * xs[k];
    }
    const M3<T> Rg = Rs[r] * so3::ExpOf<T>(psi_g);
    Eigen::Matrix<T, 6, 1> e;
    e.template head<3>() = Rg.transpose() * dx - V3<T>::UnitX();
    e.template tail<3>() = so3::RightJacobianOf<T>(psi_g) * dpsi;
    energy += 0.5 * weights[g] * 0.5 * length * e.dot(C.cast<T>() * e);
  }
  return energy;
}

Eigen::VectorXd ReferenceGradient(const std::vector<Vec3>& x, const std::vector<Mat3>& R, double length,
                                  const Mat6& C) {
  const int dofs = 6 * static_cast<int>(x.size());
  Eigen::Matrix<AutoDiff, Eigen::Dynamic, 1> p(dofs);
  for (int j = 0; j < dofs; ++j) p[j] = AutoDiff(0.0, dofs, j);
  return ReferenceEnergy<AutoDiff>(x, R, p, length, C).derivatives();
}

// ---- element states ------------------------------------------------------------------------------------

// A symmetric positive definite section with every coupling, entries of order 1..100.
Mat6 Section(test::Random* random) {
  Mat6 A;
  for (int i = 0; i < 36; ++i) A(i / 6, i % 6) = random->Uniform(-1.0, 1.0);
  Mat6 C = A * A.transpose() + Mat6::Identity();
  C.topLeftCorner<3, 3>() *= 30.0;
  return C;
}

// Nodes of an element of the given order and length: a bent, twisted and stretched beam turned by a large
// rotation, node frames a further random 0.4 rad off the beam axis.
struct ElementState {
  std::vector<NodeState> nodes;
  double length;
};

ElementState BentElement(int order, test::Random* random) {
  ElementState state;
  state.length = 0.7;
  const Mat3 R0 = random->Rotation();
  const Vec3 x0 = random->Vector(2.0);
  for (int k = 0; k <= order; ++k) {
    const double s = state.length * k / order;
    NodeState n;
    n.x = x0 + R0 * Vec3(1.05 * s, 0.2 * s * s, -0.1 * s * s) + random->Vector(0.02);
    n.R = R0 * Exp(Vec3(0.5 * s, -0.3 * s, 0.6 * s) + random->Vector(0.4));
    n.v = random->Vector(1.0);
    n.w = random->Vector(1.0);
    state.nodes.push_back(n);
  }
  return state;
}

// The context of one analysis for the element's node steps.
struct Case {
  StepContext ctx;
  std::vector<NodeStep> steps;
  void Refresh() { ctx.nodes = &steps; }
};

// Central differences of the forces with respect to the element's unknowns: one unknown moved as the
// solver moves it (PerturbNodeStep), with the end rates moving by dvf_ddx and dwf_dtheta.
Eigen::MatrixXd DifferenceTangent(const BeamElement& e, Case c) {
  const int dofs = e.num_local();
  Eigen::MatrixXd J(dofs, dofs);
  const std::vector<NodeStep> base = c.steps;
  for (int j = 0; j < dofs; ++j) {
    Eigen::VectorXd columns[2];
    for (int side = 0; side < 2; ++side) {
      const double step = side == 0 ? kStep : -kStep;
      c.steps = base;
      NodeStep& s = c.steps[j / 6];
      s = PerturbNodeStep(base[j / 6], step * Vec6::Unit(j % 6), c.ctx.mode);
      s.v_f = base[j / 6].v_f;
      s.w_f = base[j / 6].w_f;
      s.dvf_ddx = base[j / 6].dvf_ddx;
      s.dwf_dtheta = base[j / 6].dwf_dtheta;
      if (j % 6 < 3) s.v_f[j % 3] += base[j / 6].dvf_ddx * step;
      if (j % 6 >= 3) s.w_f[j % 3] += base[j / 6].dwf_dtheta * step;
      c.Refresh();
      columns[side] = test::LocalResidual(e, c.ctx);
    }
    J.col(j) = (columns[0] - columns[1]) / (2.0 * kStep);
  }
  return J;
}

void ExpectTangentMatches(const BeamElement& e, Case c, const std::string& what) {
  c.Refresh();
  const Eigen::MatrixXd analytic = test::LocalTangent(e, c.ctx);
  const Eigen::MatrixXd fd = DifferenceTangent(e, c);
  Eigen::Index row = 0, col = 0;
  const double worst = (analytic - fd).cwiseAbs().maxCoeff(&row, &col);
  EXPECT_LT(worst, kTangentTolerance * test::MaxAbs(fd))
      << what << ": entry (" << row << ", " << col << ") analytic " << analytic(row, col) << " difference "
      << fd(row, col) << " scale " << test::MaxAbs(fd);
}

std::vector<int> NodeIndices(int order) {
  std::vector<int> nodes;
  for (int k = 0; k <= order; ++k) nodes.push_back(k);
  return nodes;
}

Case StaticCase(const ElementState& state, AnalysisMode mode) {
  Case c;
  c.ctx.mode = mode;
  for (const NodeState& n : state.nodes) c.steps.push_back(MakeNodeStep(n, Vec6::Zero(), mode));
  return c;
}

TEST(BeamStrainField, ForcesAreTheGradientOfTheStrainEnergy) {
  test::Random random(21);
  for (int order = 1; order <= 3; ++order) {
    for (int trial = 0; trial < 3; ++trial) {
      const ElementState state = BentElement(order, &random);
      const Mat6 C = Section(&random);
      const BeamElement element("e", NodeIndices(order), state.length, C, 0.0);
      std::vector<Vec3> x;
      std::vector<Mat3> R;
      for (const NodeState& n : state.nodes) x.push_back(n.x), R.push_back(n.R);
      const Eigen::VectorXd reference = ReferenceGradient(x, R, state.length, C);
      Case c = StaticCase(state, AnalysisMode::kStatic);
      c.Refresh();
      const Eigen::VectorXd forces = test::LocalResidual(element, c.ctx);
      EXPECT_LT((forces - reference).cwiseAbs().maxCoeff(), kForceTolerance * test::MaxAbs(reference))
          << "order " << order << "\nanalytic " << forces.transpose() << "\nreference " << reference.transpose();
    }
  }
}

// A step's tangent in one pass of (dz/dp)_mid^T (docs/theory.md, (B12)) against its parts formed apart, at two
// random bent configurations with random stresses, section matrices and increment maps: the material part
// B_mid^T rate B_f M_f, plus the geometric part K_geo M_mid when asked for, and K_geo^T d either way. The same
// terms summed in another order: round-off of sums of ~100 terms, 1e-12 of the largest entry.
TEST(BeamStrainField, StepTangentIsItsMaterialAndGeometricPartsInTheIncrements) {
  constexpr double kReorderedSumTolerance = 1.0e-12;
  using Field = BeamStrainField;
  test::Random random(28);
  for (int order = 1; order <= 3; ++order) {
    const ElementState mid_state = BentElement(order, &random), end_state = BentElement(order, &random);
    const BeamShape shape = GaussShape(order, mid_state.length);
    Field::Nodes mid_nodes, end_nodes;
    for (int k = 0; k <= order; ++k) {
      mid_nodes.x[k] = mid_state.nodes[k].x;
      mid_nodes.R[k] = mid_state.nodes[k].R;
      end_nodes.x[k] = end_state.nodes[k].x;
      end_nodes.R[k] = end_state.nodes[k].R;
    }
    const Field mid(shape, mid_nodes, Field::Order::kSecond), end(shape, end_nodes, Field::Order::kFirst);
    Field::PointVectors stress;
    std::array<Mat6, Field::kMaxPoints> material;
    for (int g = 0; g < shape.num_points; ++g) {
      stress[g] = random.VectorX(6, 1.0e3);
      material[g] = Section(&random);
    }
    Field::IncrementMap map, end_map;
    map.translation_rate = 0.5;
    for (int k = 0; k <= order; ++k) {
      map.rotation[k] = 0.5 * RightJacobian(random.Vector(0.5));
      end_map.rotation[k] = RightJacobian(random.Vector(0.5));
    }
    const int n = order + 1, dofs = 6 * n;
    const Field::Vector d = random.VectorX(dofs, 0.1);

    Field::Matrix K_geo = Field::Matrix::Zero(dofs, dofs);
    mid.AddTangent(stress, nullptr, &K_geo);
    map.ApplyToColumns(n, &K_geo);
    Field::Matrix K_mat = mid.MaterialTangent(end, material);
    end_map.ApplyToColumns(n, &K_mat);
    const Field::Vector K_geo_transposed_d = K_geo.transpose() * d;

    for (bool geometric : {false, true}) {
      Field::Matrix K = Field::Matrix::Zero(dofs, dofs);
      const Field::Vector returned = mid.AddStepTangent(stress, end, material, map, end_map, geometric, d, &K);
      const Field::Matrix expected = geometric ? Field::Matrix(K_mat + K_geo) : K_mat;
      EXPECT_LT((K - expected).cwiseAbs().maxCoeff(), kReorderedSumTolerance * test::MaxAbs(expected))
          << "order " << order << " geometric " << geometric;
      EXPECT_LT((returned - K_geo_transposed_d).cwiseAbs().maxCoeff(),
                kReorderedSumTolerance * test::MaxAbs(K_geo_transposed_d))
          << "order " << order << " geometric " << geometric;
    }
  }
}

TEST(BeamElement, StaticTangentIsExact) {
  test::Random random(22);
  for (int order = 1; order <= 3; ++order) {
    for (int trial = 0; trial < 3; ++trial) {
      const ElementState state = BentElement(order, &random);
      const BeamElement element("e", NodeIndices(order), state.length, Section(&random), 0.0);
      ExpectTangentMatches(element, StaticCase(state, AnalysisMode::kStatic), "static order " + std::to_string(order));
    }
  }
}

TEST(BeamElement, EndPointTangentWithDampingIsExact) {
  test::Random random(23);
  for (int order = 1; order <= 3; ++order) {
    const ElementState state = BentElement(order, &random);
    const BeamElement element("e", NodeIndices(order), state.length, Section(&random), 0.05);
    Case c = StaticCase(state, AnalysisMode::kEndPoint);
    for (size_t k = 0; k < c.steps.size(); ++k) {
      c.steps[k].v_f = state.nodes[k].v;
      c.steps[k].w_f = state.nodes[k].w;
      c.steps[k].dvf_ddx = 30.0;
      c.steps[k].dwf_dtheta = 20.0;
    }
    ExpectTangentMatches(element, c, "end point order " + std::to_string(order));
  }
}

TEST(BeamElement, EndPointRatePartsAreTheDampingDerivatives) {
  // Reference: central differences of the end-point forces in the end rates (v_f, w_f): D is B^T mu C B (B7);
  // nothing reads accelerations (M = 0); statics and the dynamic step read no end rates. The forces are linear
  // in the rates, so the differences are exact to round-off, ~1e-16 |r| / 1e-6 = 1e-10 of the largest entry.
  constexpr double kRateStep = 1.0e-6, kRateTolerance = 1.0e-8;
  test::Random random(24);
  for (int order = 1; order <= 3; ++order) {
    const ElementState state = BentElement(order, &random);
    const BeamElement element("e", NodeIndices(order), state.length, Section(&random), 0.05);
    EXPECT_FALSE(element.HasRateParts(AnalysisMode::kStatic));
    EXPECT_FALSE(element.HasRateParts(AnalysisMode::kDynamic));
    Case c = StaticCase(state, AnalysisMode::kEndPoint);
    for (size_t k = 0; k < c.steps.size(); ++k) {
      c.steps[k].v_f = state.nodes[k].v;
      c.steps[k].w_f = state.nodes[k].w;
    }
    c.Refresh();
    const test::RateParts parts = test::LocalRateParts(element, c.ctx);
    const Eigen::MatrixXd D = test::RateDifferences(element, c.ctx, false, kRateStep);
    EXPECT_GT(test::MaxAbs(D), 0.0);
    EXPECT_LT(test::MaxAbs(parts.D - D), kRateTolerance * test::MaxAbs(D)) << "order " << order;
    EXPECT_EQ(test::MaxAbs(parts.M), 0.0);
    EXPECT_EQ(test::MaxAbs(test::RateDifferences(element, c.ctx, true, kRateStep)), 0.0);
  }
}

Case DynamicCase(const ElementState& state, test::Random* random) {
  Case c;
  c.ctx.mode = AnalysisMode::kDynamic;
  c.ctx.h = 0.01;
  c.ctx.geometric_stiffness = true;  // the exact tangent (a step's first tangent leaves the geometric part out)
  for (const NodeState& n : state.nodes) {
    Vec6 increment;
    increment << random->Vector(0.05), random->Vector(0.3);
    c.steps.push_back(MakeNodeStep(n, increment, AnalysisMode::kDynamic));
  }
  return c;
}

// The energy-decaying scheme's dissipation of the strains (B13) in a case: alpha for the element (index 0) and a
// start state holding a previous step of 0.8 h with random strain changes of the size of this step's.
struct SchemeDissipation {
  std::vector<double> alpha{0.05};
  State start;
  SchemeDissipation(BeamElement* element, Case* c, test::Random* random) {
    element->set_index(0);
    start.h_prev = 0.8 * c->ctx.h;
    start.element_history = {random->VectorX(element->history_size(), 1.0e-2)};
    c->ctx.start = &start;
    c->ctx.element_alpha = &alpha;
  }
};

TEST(BeamElement, DynamicTangentIsExact) {
  test::Random random(24);
  for (int order = 1; order <= 3; ++order) {
    for (double damping : {0.0, 0.02}) {
      const ElementState state = BentElement(order, &random);
      const BeamElement element("e", NodeIndices(order), state.length, Section(&random), damping);
      ExpectTangentMatches(element, DynamicCase(state, &random),
                           "dynamic order " + std::to_string(order) + " damping " + std::to_string(damping));
    }
  }
}

TEST(BeamElement, DynamicTangentWithSchemeDissipationIsExact) {
  test::Random random(26);
  for (int order = 1; order <= 3; ++order) {
    for (double damping : {0.0, 0.02}) {
      const ElementState state = BentElement(order, &random);
      BeamElement element("e", NodeIndices(order), state.length, Section(&random), damping);
      Case c = DynamicCase(state, &random);
      const SchemeDissipation scheme(&element, &c, &random);
      ExpectTangentMatches(element, c, "dynamic order " + std::to_string(order) + " damping " +
                                           std::to_string(damping) + " with the scheme's dissipation");
    }
  }
}

// A beam keeps the strains of the start and end configurations it was last evaluated at in its workspace
// (BeamElement::StrainMemo) and reads them back only for the very same nodes: evaluated after other steps, from
// another start and to another end, an element with a workspace gives exactly the forces, tangent and step work
// of one without.
TEST(BeamElement, WorkspaceGivesTheForcesOfTheStepAskedAbout) {
  test::Random random(29);
  for (int order = 1; order <= 3; ++order) {
    std::vector<std::unique_ptr<Element>> elements;
    elements.push_back(std::make_unique<BeamElement>("e", NodeIndices(order), 0.7, Section(&random), 0.02));
    const Element& beam = *elements[0];
    elements[0]->set_index(0);
    ElementWorkspaces workspaces(elements);
    const ElementState first_state = BentElement(order, &random), second_state = BentElement(order, &random);
    // A step from another start, then two steps from one start to different ends.
    const std::vector<Case> cases = {DynamicCase(first_state, &random), DynamicCase(second_state, &random),
                                     DynamicCase(second_state, &random)};
    for (size_t k = 0; k < cases.size(); ++k) {
      Case fresh = cases[k], kept = cases[k];
      fresh.Refresh();
      kept.Refresh();
      kept.ctx.workspaces = &workspaces;
      // The same arithmetic on the same numbers: equal to the last bit.
      EXPECT_EQ(test::LocalResidual(beam, kept.ctx), test::LocalResidual(beam, fresh.ctx)) << "case " << k;
      EXPECT_EQ(test::LocalTangent(beam, kept.ctx), test::LocalTangent(beam, fresh.ctx)) << "case " << k;
      StepWork with, without;
      beam.AddStepWork(kept.ctx, &with);
      beam.AddStepWork(fresh.ctx, &without);
      EXPECT_EQ(with.dissipated, without.dissipated) << "case " << k;
    }
  }
}

// A step's first tangent (ctx.geometric_stiffness off) leaves out the geometric stiffness of the section forces,
// which the predictor's spurious stretch would make up (docs/theory.md, "Newton iteration"): it equals the exact
// tangent where the step's stresses vanish (an unstrained straight beam turned rigidly), and differs from it on
// a bent beam.
TEST(BeamElement, FirstTangentOfAStepLeavesOutOnlyTheGeometricStiffness) {
  test::Random random(27);
  for (int order = 1; order <= 3; ++order) {
    const double length = 0.7;
    const BeamElement element("e", NodeIndices(order), length, Section(&random), 0.02);
    const Mat3 R0 = random.Rotation();
    const Vec3 x0 = random.Vector(2.0), turn = random.Vector(0.3), shift = random.Vector(0.05);
    Case rigid;
    rigid.ctx.mode = AnalysisMode::kDynamic;
    rigid.ctx.h = 0.01;
    for (int k = 0; k <= order; ++k) {
      NodeState n;
      n.x = x0 + R0 * Vec3(length * k / order, 0.0, 0.0);
      n.R = R0;
      Vec6 increment;
      increment << (Exp(turn) - Mat3::Identity()) * (n.x - x0) + shift, R0.transpose() * turn;
      rigid.steps.push_back(MakeNodeStep(n, increment, AnalysisMode::kDynamic));
    }
    rigid.Refresh();
    const Eigen::MatrixXd first = test::LocalTangent(element, rigid.ctx);
    rigid.ctx.geometric_stiffness = true;
    const Eigen::MatrixXd exact = test::LocalTangent(element, rigid.ctx);
    // Both are sums of the same material terms of size |C| / length; what is left is round-off of the
    // strains of a rigid motion (eps |C| per term).
    EXPECT_LT((first - exact).cwiseAbs().maxCoeff(), 1.0e-10 * test::MaxAbs(exact)) << "order " << order;

    Case bent = DynamicCase(BentElement(order, &random), &random);
    bent.Refresh();
    const Eigen::MatrixXd bent_exact = test::LocalTangent(element, bent.ctx);
    bent.ctx.geometric_stiffness = false;
    // The bent beam's stresses are of the order of its stiffness: the geometric part is a sizeable fraction.
    EXPECT_GT((test::LocalTangent(element, bent.ctx) - bent_exact).cwiseAbs().maxCoeff(),
              1.0e-3 * test::MaxAbs(bent_exact))
        << "order " << order;
  }
}

// The step's forces are an exact discrete gradient (B5): G . d = V_f - V_i, and the damping forces do the
// work -mu sum_g w_g de^T C de / h (B7).
TEST(BeamElement, StepForcesCloseTheEnergyBooks) {
  test::Random random(25);
  for (int order = 1; order <= 3; ++order) {
    const ElementState state = BentElement(order, &random);
    const Mat6 C = Section(&random);
    const double mu = 0.02;
    const BeamElement elastic("e", NodeIndices(order), state.length, C, 0.0);
    const BeamElement damped("e", NodeIndices(order), state.length, C, mu);
    Case c = DynamicCase(state, &random);
    c.Refresh();
    Eigen::VectorXd d(6 * (order + 1));
    State start, end;
    for (size_t k = 0; k < c.steps.size(); ++k) {
      d << Eigen::VectorXd(d).head(6 * k), c.steps[k].dx, c.steps[k].theta, Eigen::VectorXd::Zero(6 * (order - k));
      NodeState i = state.nodes[k], f = state.nodes[k];
      f.x = c.steps[k].x_f;
      f.R = c.steps[k].R_f;
      start.nodes.push_back(i);
      end.nodes.push_back(f);
    }
    EnergyTally V_i, V_f;
    elastic.AddEnergy(start, Vec3::Zero(), &V_i);
    elastic.AddEnergy(end, Vec3::Zero(), &V_f);
    const double work = test::LocalResidual(elastic, c.ctx).dot(d);
    // Round-off of energies of order 1 J summed over a few points.
    EXPECT_NEAR(work, V_f.potential - V_i.potential, 1e-12 * std::max(1.0, std::abs(V_f.potential)));
    StepWork dissipation;
    damped.AddStepWork(c.ctx, &dissipation);
    EXPECT_GT(dissipation.dissipated, 0.0);
    EXPECT_NEAR(test::LocalResidual(damped, c.ctx).dot(d) - work, dissipation.dissipated,
                1e-12 * std::max(1.0, dissipation.dissipated));
    // The scheme's dissipation of the strains does the work alpha sum_g w_g (de - de_lagged)^T C de (B13),
    // booked as numerical.
    BeamElement decaying("e", NodeIndices(order), state.length, C, mu);
    const SchemeDissipation scheme(&decaying, &c, &random);
    StepWork both;
    decaying.AddStepWork(c.ctx, &both);
    EXPECT_NEAR(both.dissipated, dissipation.dissipated, 1e-12 * std::max(1.0, dissipation.dissipated));
    EXPECT_NE(both.numerical, 0.0);
    EXPECT_NEAR(test::LocalResidual(decaying, c.ctx).dot(d) - work, both.dissipated + both.numerical,
                1e-12 * std::max(1.0, both.dissipated + std::abs(both.numerical)));
  }
}

}  // namespace beam_tangent_test
}  // namespace flexmbd
