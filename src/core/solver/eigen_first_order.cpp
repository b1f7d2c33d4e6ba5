// Dense eigen-solution of a linearised system with element states (docs/theory.md, (E7)): the node and joint
// variables keep their second-order form, reduced and mass-normalised as in (E4); the element states join as
// first-order rows, and the generalized problem E z' = A z is solved for every root.

#include <Eigen/Dense>

#include "dense_decompositions.hpp"
#include "eigen_internal.hpp"

namespace flexmbd {
namespace eigen_internal {
namespace {
// Round-off of a root as a fraction of |s| (theory (E7)): E^-1 A is not scaled (entries from 1 to the square of the
// largest root), and eps |A|_F times a root's condition number overstates its round-off ~1e3 times (the Goland wing's
// flutter root at 11 Hz, damping ratio -0.038, was estimated at 0.34 1/s: no flutter). Undamped roots of this solve
// come out with ratios of ~1e-9 of either sign (the Goland wing's: up to -3.8e-8 at 5e-3 of the largest root).
constexpr double kRoundOffRatio = 1.0e-9;
}  // namespace

EigenResult SolveDenseWithStates(const Model& model, const LinearisedSystem& system, const EigenOptions& options) {
  const int nk = static_cast<int>(system.M.rows()), ns = model.num_element_states(), nq = nk - ns;
  const Eigen::MatrixXd K(system.K), D(system.D), M(system.M);
  const ConstraintNullSpace null_space(Eigen::MatrixXd(system.B).leftCols(nq), nq);
  const Eigen::MatrixXd& Z = null_space.Z();
  const int r = static_cast<int>(Z.cols());
  // y = T c with T^T M_qq T = I over the constrained motions c (theory (E4)).
  const Eigen::MatrixXd T = Z * MassNormalisingBasis(model, Z.transpose() * M.topLeftCorner(nq, nq) * Z, Z);
  const Eigen::MatrixXd Tt = T.transpose();

  EigenResult result;
  result.method = "dense";
  result.num_kinematic = nk;
  result.num_dof = r;
  result.num_states = ns;
  // z = (c, c', x):  c' = p;  p' + Tt D_qx x' = -Tt K_qq T c - Tt D_qq T p - Tt K_qx x;
  // M_xq T p' + D_xx x' = -K_xq T c - D_xq T p - K_xx x   (theory (E7)).
  const int n = 2 * r + ns;
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, n), A = Eigen::MatrixXd::Zero(n, n);
  E.topLeftCorner(2 * r, 2 * r).setIdentity();
  E.block(r, 2 * r, r, ns) = Tt * D.topRightCorner(nq, ns);
  E.block(2 * r, r, ns, r) = M.bottomLeftCorner(ns, nq) * T;
  E.bottomRightCorner(ns, ns) = D.bottomRightCorner(ns, ns);
  A.block(0, r, r, r).setIdentity();
  A.block(r, 0, r, r) = -Tt * K.topLeftCorner(nq, nq) * T;
  A.block(r, r, r, r) = -Tt * D.topLeftCorner(nq, nq) * T;
  A.block(r, 2 * r, r, ns) = -Tt * K.topRightCorner(nq, ns);
  A.block(2 * r, 0, ns, r) = -K.bottomLeftCorner(ns, nq) * T;
  A.block(2 * r, r, ns, r) = -D.bottomLeftCorner(ns, nq) * T;
  A.bottomRightCorner(ns, ns) = -K.bottomRightCorner(ns, ns);
  const Eigen::MatrixXd system_matrix = Eigen::PartialPivLU<Eigen::MatrixXd>(E).solve(A);
  const dense::Eigenpairs eig = dense::GeneralEigen(system_matrix);
  std::vector<RawMode> raw;
  for (int i = 0; i < n; ++i) {
    RawMode mode;
    mode.s = eig.values[i];
    mode.round_off = kRoundOffRatio * std::abs(eig.values[i]);
    mode.x.resize(nk);
    mode.x.head(nq) = T.cast<std::complex<double>>() * eig.vectors.col(i).head(r);
    mode.x.tail(ns) = eig.vectors.col(i).tail(ns);
    raw.push_back(std::move(mode));
  }
  // Frequency scale: the largest root, against which rigid-body roots are judged (theory (E5)).
  double scale = eig.values.cwiseAbs().maxCoeff();
  if (!(scale > 0)) scale = 1.0;
  ClassifyModes(model, system, raw, false, ns, scale, options.rigid_tolerance * scale, options, &result);
  return result;
}

}  // namespace eigen_internal
}  // namespace flexmbd
