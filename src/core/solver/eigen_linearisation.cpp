// Linearisation about a state (docs/theory.md, eqs. (E1)-(E3)): K, D, M and B from the parts of the elements'
// end-point tangents, the rotation-rate correction of rotating nodes, and consistent accelerations and multipliers.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>

#include "drive_rows.hpp"
#include "eigen_internal.hpp"
#include "flexmbd/common/error.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {
namespace {

using eigen_internal::ConstraintNullSpace;
using eigen_internal::KluLu;
using Triplets = std::vector<Eigen::Triplet<double>>;

// Step along the motion, as a fraction of its time scale 1 / (largest rate), of the second differences that
// give the constraints' velocity terms, extrapolated from steps e and e/2 (Richardson): truncation e^4 = 1e-12
// against round-off eps / (e/2)^2 = 1e-9 relative.
constexpr double kMotionStep = 1.0e-3;
// Largest number of kinematic unknowns whose consistent accelerations are solved by the dense null space when
// the sparse saddle-point solve fails.
constexpr int kDenseReferenceLimit = 2000;
// The saddle-point solve is rejected below this reciprocal condition estimate (dependent constraint rows give
// round-off, ~1e-17) or when its residual exceeds this fraction of the terms it balances.
constexpr double kSaddleConditionLimit = 1.0e-13;
constexpr double kSaddleResidual = 1.0e-10;

// End-point evaluations at one state: node and variable rates and accelerations from the state, no increment.
class Probe {
 public:
  Probe(const Model& model, const State& state) : builder_(model) {
    Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model.num_unknowns());
    unknowns.tail(model.num_multipliers()) = state.lambda;
    ctx_ = &builder_.EndPoint(state, unknowns, state.t, 1.0);
    for (int k = 0; k < model.num_nodes(); ++k) {
      NodeStep& s = builder_.nodes()[k];
      const NodeState& n = state.nodes[k];
      s.v_i = s.v_f = n.v;
      s.w_i = s.w_f = n.w;
      s.vdot_f = n.a_prev;
      s.wdot_f = n.alpha_prev;
    }
    for (int k = 0; k < model.num_variables(); ++k) builder_.variables()[k].qdot_f = state.qdot[k];
    builder_.set_geometric_stiffness(true);
  }

  // The element's tangent parts (Element::AddTangent, AddRateParts): K with the geometric stiffness of
  // constraint forces and loads, D = dr/d(rates) and M = dr/d(accelerations).
  void Parts(const Element& e, Eigen::MatrixXd* K, Eigen::MatrixXd* D, Eigen::MatrixXd* M) const {
    const int n = e.num_local();
    K->setZero(n, n);
    D->setZero(n, n);
    M->setZero(n, n);
    e.AddTangent(*ctx_, *K);
    if (e.HasRateParts(ctx_->mode)) e.AddRateParts(*ctx_, *D, *M);
  }

  Eigen::VectorXd Residual(const Element& e) const {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(e.num_local()), magnitude = Eigen::VectorXd::Zero(e.num_local());
    e.AddResidual(*ctx_, r, magnitude);
    return r;
  }

 private:
  StepContextBuilder builder_;
  const StepContext* ctx_ = nullptr;
};

// Element-assembled matrices and residual at one state.
struct Assembled {
  Eigen::VectorXd residual;             ///< all rows
  Eigen::SparseMatrix<double> K, D, M;  ///< force rows x kinematic columns, without the rotation-rate terms
  Eigen::SparseMatrix<double> B;        ///< constraint rows x kinematic columns
  Eigen::SparseMatrix<double> Gt;       ///< force rows x multiplier columns
  Eigen::SparseMatrix<double> C;        ///< constraint rows x multiplier columns
};

Assembled Assemble(const Model& model, const State& state) {
  const int nk = model.num_unknowns() - model.num_multipliers(), m = model.num_multipliers();
  Probe probe(model, state);
  Triplets k, d, mass, b, gt, c;
  Assembled out;
  out.residual = Eigen::VectorXd::Zero(model.num_unknowns());
  Eigen::MatrixXd K, D, M;
  for (const auto& element : model.elements()) {
    const Element& e = *element;
    const std::vector<int>& u = e.unknowns();
    const int n = e.num_local();
    const Eigen::VectorXd r = probe.Residual(e);
    for (int i = 0; i < n; ++i) out.residual[u[i]] += r[i];
    probe.Parts(e, &K, &D, &M);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const bool force_row = model.is_force_row(u[i]), kinematic_column = model.is_force_row(u[j]);
        if (force_row && kinematic_column) {
          if (K(i, j) != 0.0) k.emplace_back(u[i], u[j], K(i, j));
          if (D(i, j) != 0.0) d.emplace_back(u[i], u[j], D(i, j));
          if (M(i, j) != 0.0) mass.emplace_back(u[i], u[j], M(i, j));
        } else if (kinematic_column) {
          if (K(i, j) != 0.0) b.emplace_back(u[i] - nk, u[j], K(i, j));
        } else if (force_row) {
          if (K(i, j) != 0.0) gt.emplace_back(u[i], u[j] - nk, K(i, j));
        } else if (K(i, j) != 0.0) {
          c.emplace_back(u[i] - nk, u[j] - nk, K(i, j));
        }
      }
    }
  }
  auto build = [](int rows, int cols, const Triplets& t) {
    Eigen::SparseMatrix<double> A(rows, cols);
    A.setFromTriplets(t.begin(), t.end());
    return A;
  };
  out.K = build(nk, nk, k);
  out.D = build(nk, nk, d);
  out.M = build(nk, nk, mass);
  out.B = build(m, nk, b);
  out.Gt = build(nk, m, gt);
  out.C = build(m, m, c);
  return out;
}

// Kinematic velocity vector u = (v, w per node, qdot, element state rates) of a state.
Eigen::VectorXd Rates(const Model& model, const State& state) {
  Eigen::VectorXd u(model.num_kinematic());
  for (int k = 0; k < model.num_nodes(); ++k) u.segment<6>(6 * k) << state.nodes[k].v, state.nodes[k].w;
  u.segment(model.variable_unknown(0), model.num_variables()) = state.qdot;
  u.tail(model.num_element_states()) = state.element_state_rates;
  return u;
}

// Second time derivative of the constraint rows along the motion with constant rates u (body-frame angular
// velocities, joint rates) and time: the terms of Phi'' that do not involve accelerations (theory (E2)). The
// motion's part is differenced; the time's, which only drives have (q - f(t)), is the law's -f''(t), one-sided at a
// kink: a difference across the start of a law that starts moving (a sine or a ramp from t = 0) read its jump of
// rate as an acceleration f'/e.
Eigen::VectorXd ConstraintCurvature(const Model& model, const State& state) {
  const int n = model.num_unknowns(), m = model.num_multipliers(), nk = n - m;
  const Eigen::VectorXd u = Rates(model, state);
  const double rate = eigen_internal::ReferenceRate(model, state);
  const double step = kMotionStep / (rate > 0 ? rate : 1.0);
  StepContextBuilder builder(model);
  auto constraints = [&](double e) {
    Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(n);
    unknowns.head(nk) = e * u;
    unknowns.tail(m) = state.lambda;
    const StepContext& ctx = builder.EndPoint(state, unknowns, state.t, 1.0);
    Eigen::VectorXd phi = Eigen::VectorXd::Zero(m);
    for (const auto& element : model.elements()) {
      const std::vector<int>& local = element->unknowns();
      Eigen::VectorXd r = Eigen::VectorXd::Zero(element->num_local()), mag = r;
      element->AddResidual(ctx, r, mag);
      for (int i = 0; i < element->num_local(); ++i) {
        if (!model.is_force_row(local[i])) phi[local[i] - nk] += r[i];
      }
    }
    return phi;
  };
  const Eigen::VectorXd at_rest = constraints(0.0);
  auto second_difference = [&](double e) -> Eigen::VectorXd {
    return (constraints(e) - 2.0 * at_rest + constraints(-e)) / (e * e);
  };
  return (4.0 * second_difference(0.5 * step) - second_difference(step)) / 3.0 -
         DriveLawDerivatives(model, state, 2);
}

// Writes accelerations (node v', w' in the node frame, q'') into a state.
void SetAccelerations(const Model& model, const Eigen::VectorXd& acceleration, State* state) {
  for (int k = 0; k < model.num_nodes(); ++k) {
    state->nodes[k].a_prev = acceleration.segment<3>(6 * k);
    state->nodes[k].alpha_prev = acceleration.segment<3>(6 * k + 3);
  }
  state->qddot_prev = acceleration.segment(model.variable_unknown(0), model.num_variables());
}

// The rows and columns of the second-order unknowns (nodes, joint variables): the element states keep their
// values and stored rates in the reference motion (theory (E2)).
Assembled SecondOrderPart(const Assembled& a, int nq) {
  Assembled out;
  out.residual = a.residual.head(nq);
  out.K = a.K.topLeftCorner(nq, nq);
  out.D = a.D.topLeftCorner(nq, nq);
  out.M = a.M.topLeftCorner(nq, nq);
  out.B = a.B.leftCols(nq);
  out.Gt = a.Gt.topRows(nq);
  return out;
}

// Solves the saddle-point system [M G^T; B 0] (a, lambda) = (-r0, -gamma) by KLU. Returns false if the matrix
// is singular or so ill-conditioned that the solve does not reproduce the right-hand side (dependent
// constraint rows make it singular).
bool SolveSaddle(const Assembled& a, const Eigen::VectorXd& r0, const Eigen::VectorXd& gamma,
                 Eigen::VectorXd* acceleration, Eigen::VectorXd* lambda) {
  const int nk = static_cast<int>(a.M.rows()), m = static_cast<int>(a.B.rows());
  Triplets t;
  for (int j = 0; j < nk; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a.M, j); it; ++it) t.emplace_back(it.row(), j, it.value());
    for (Eigen::SparseMatrix<double>::InnerIterator it(a.B, j); it; ++it) t.emplace_back(nk + it.row(), j, it.value());
  }
  for (int j = 0; j < m; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a.Gt, j); it; ++it) t.emplace_back(it.row(), nk + j, it.value());
  }
  Eigen::SparseMatrix<double> saddle(nk + m, nk + m);
  saddle.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd rhs(nk + m);
  rhs << -r0, -gamma;
  Eigen::VectorXd x = rhs;
  KluLu lu;
  if (!lu.Factorise(saddle) || lu.rcond() < kSaddleConditionLimit || !lu.Solve(&x)) return false;
  saddle.makeCompressed();
  const double scale = saddle.coeffs().cwiseAbs().maxCoeff() * x.cwiseAbs().maxCoeff() + rhs.cwiseAbs().maxCoeff();
  if (!((saddle * x - rhs).cwiseAbs().maxCoeff() <= kSaddleResidual * scale)) return false;
  *acceleration = x.head(nk);
  *lambda = x.tail(m);
  return true;
}

// Accelerations and multipliers that satisfy the equations of motion at the state's positions and velocities:
//   M a + G^T lambda = -r0,   B a = -gamma   (theory (E2)).
// By KLU on the saddle-point system; by the null space of B when that fails on a small model (dependent
// constraint rows, or a motion without inertia, which the null-space path names).
void SolveReferenceMotion(const Model& model, State* state) {
  const int nk = model.element_state_unknown(0), m = model.num_multipliers();
  SetAccelerations(model, Eigen::VectorXd::Zero(nk), state);
  state->lambda.setZero();
  const Assembled a = SecondOrderPart(Assemble(model, *state), nk);
  const Eigen::VectorXd r0 = a.residual.head(nk);
  const Eigen::VectorXd gamma = m > 0 ? ConstraintCurvature(model, *state) : Eigen::VectorXd();
  Eigen::VectorXd acceleration, lambda;
  if (!SolveSaddle(a, r0, gamma, &acceleration, &lambda)) {
    if (nk > kDenseReferenceLimit) {
      throw SolverError(
          "eigen-analysis: cannot solve for the accelerations and multipliers at the state (the system "
          "[M G^T; B 0] is singular: dependent constraint rows, or a motion without inertia)");
    }
    const Eigen::MatrixXd M = Eigen::MatrixXd(a.M);
    const ConstraintNullSpace null_space(Eigen::MatrixXd(a.B), nk);
    const Eigen::MatrixXd& Z = null_space.Z();
    const Eigen::VectorXd particular = m > 0 ? null_space.MinimumNormSolution(-gamma) : Eigen::VectorXd::Zero(nk);
    const Eigen::MatrixXd W = eigen_internal::MassNormalisingBasis(model, Z.transpose() * M * Z, Z);
    acceleration = particular - Z * (W * (W.transpose() * (Z.transpose() * (r0 + M * particular))));
    if (m > 0) {
      lambda = Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd(a.Gt)).solve(-(r0 + M * acceleration));
    }
  }
  SetAccelerations(model, acceleration, state);
  if (m > 0) state->lambda = lambda;
}

// Coordinates of the perturbation (theory (E3)): per node, translation xi and rotation theta in the node
// frame, dx = R xi, R_perturbed = R Exp(theta); joint variables as they are. With W = Skew(w), Wd = Skew(w')
// of the reference, the perturbed velocities and accelerations in the unknowns' own terms (v in W, w in the
// node frame) are P (y' + X y) and P (y'' + A1 y' + A0 y), P = diag(R, I) per node, and
//   X = diag(W, W),   A1 = diag(2 W, W),   A0 = diag(W^2 + Wd, Wd).
struct Kinematics {
  Eigen::SparseMatrix<double> P, X, A1, A0;
};

Kinematics PerturbationKinematics(const Model& model, const State& state) {
  const int nk = model.num_unknowns() - model.num_multipliers();
  Triplets p, x, a1, a0;
  auto block = [](Triplets* t, int at, const Mat3& A) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (A(i, j) != 0.0) t->emplace_back(at + i, at + j, A(i, j));
      }
    }
  };
  for (int k = 0; k < model.num_nodes(); ++k) {
    const NodeState& n = state.nodes[k];
    const Mat3 W = Skew(n.w), Wd = Skew(n.alpha_prev);
    const int t = 6 * k, r = 6 * k + 3;
    block(&p, t, n.R);
    block(&p, r, Mat3::Identity());
    block(&x, t, W);
    block(&x, r, W);
    block(&a1, t, 2.0 * W);
    block(&a1, r, W);
    block(&a0, t, W * W + Wd);
    block(&a0, r, Wd);
  }
  for (int v = 6 * model.num_nodes(); v < nk; ++v) p.emplace_back(v, v, 1.0);
  Kinematics out;
  for (auto [matrix, triplets] : {std::make_pair(&out.P, &p), std::make_pair(&out.X, &x), std::make_pair(&out.A1, &a1),
                                  std::make_pair(&out.A0, &a0)}) {
    matrix->resize(nk, nk);
    matrix->setFromTriplets(triplets->begin(), triplets->end());
  }
  return out;
}

// The state with every per-variable and per-multiplier vector sized to the model.
State Sized(const Model& model, const State& state) {
  const int nv = model.num_variables();
  State out = state;
  if (out.qddot_prev.size() != nv) out.qddot_prev = Eigen::VectorXd::Zero(nv);
  if (out.qdot.size() != nv) out.qdot = Eigen::VectorXd::Zero(nv);
  if (out.lambda.size() != model.num_multipliers()) out.lambda = Eigen::VectorXd::Zero(model.num_multipliers());
  return out;
}

}  // namespace

double eigen_internal::ReferenceRate(const Model& model, const State& state) {
  double rate = 0;
  for (int k = 0; k < model.num_nodes(); ++k) {
    rate = std::max({rate, state.nodes[k].w.norm(), state.nodes[k].v.norm() / model.length_scale()});
  }
  if (model.num_variables() > 0) rate = std::max(rate, state.qdot.cwiseAbs().maxCoeff());
  return rate;
}

State WithConsistentMotion(const Model& model, const State& state) {
  State out = Sized(model, state);
  SolveReferenceMotion(model, &out);
  return out;
}

LinearisedSystem Linearise(const Model& model, const State& state, ReferenceMotion reference) {
  LinearisedSystem out;
  out.reference = Sized(model, state);
  State& ref = out.reference;
  switch (reference) {
    case ReferenceMotion::kConsistent:
      SolveReferenceMotion(model, &ref);
      break;
    case ReferenceMotion::kZeroAcceleration:
      SetAccelerations(model, Eigen::VectorXd::Zero(model.element_state_unknown(0)), &ref);
      break;
    case ReferenceMotion::kFromState:
      break;
  }
  const Assembled a = Assemble(model, ref);
  // delta r = K_e dx + D_e dv + M_e da with dx = P y and the rates of Kinematics, rows turned by P^T.
  const Kinematics c = PerturbationKinematics(model, ref);
  const Eigen::SparseMatrix<double> Pt = c.P.transpose();
  const Eigen::SparseMatrix<double> KP = a.K * c.P, DP = a.D * c.P, MP = a.M * c.P;
  out.M = Pt * MP;
  out.D = Pt * (DP + MP * c.A1);
  out.K = Pt * (KP + DP * c.X + MP * c.A0);
  out.B = a.B * c.P;
  out.C = a.C;
  out.T = c.P;
  out.residual = a.residual;
  out.residual.head(Pt.rows()) = Pt * a.residual.head(Pt.rows());
  out.K.prune(0.0);
  out.D.prune(0.0);
  out.B.prune(0.0);
  return out;
}

}  // namespace flexmbd
