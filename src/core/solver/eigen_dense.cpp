// Dense eigen-solution of a linearised system (docs/theory.md, eqs. (E4)-(E5)): null-space elimination of
// the constraints, mass normalisation, and either the symmetric problem (no damping or gyroscopic terms,
// symmetric stiffness) or the first-order state-space problem.

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <iterator>

#include "eigen_internal.hpp"

namespace flexmbd {
namespace eigen_internal {
namespace {
// Relative asymmetry of the reduced stiffness accepted as symmetric: the central-difference stiffness of
// constraint forces is symmetric to about 1e-10; genuine asymmetry (follower loads, non-equilibrium states,
// rotating frames) is of order one.
constexpr double kSymmetryTolerance = 1.0e-7;
// Shift of the inverted problem, as a fraction of the model's frequency scale w (theory (E5)). Inverted about
// -k w, a root s has a relative error ~eps (|s| + k w)^2 / (k w |s|); solved directly, ~eps w / |s|.
// Roots below sqrt(k) w come from the inverted problem, the others from the direct one: every root is then
// good to ~eps / sqrt(k) = 2e-14, down to roots of k w (in frequency; symmetric: k^2 w^2 in omega^2) and to
// eps k w / |s| below, e.g. 2e-9 at 1e-11 w, the lowest frequencies of stiff finite-element models.
constexpr double kShift = 1.0e-4;

// Roots of the symmetric problem Kt v = omega^2 v, from (Kt + a I)^{-1} if a > 0, else directly.
std::vector<RawMode> SymmetricRoots(const Eigen::MatrixXd& Kt, const Eigen::MatrixXd& T, double a) {
  Eigen::MatrixXd matrix = 0.5 * (Kt + Kt.transpose());
  if (a > 0) {
    matrix.diagonal().array() += a;
    matrix = Eigen::PartialPivLU<Eigen::MatrixXd>(matrix).inverse();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (matrix + matrix.transpose()));
  std::vector<RawMode> out;
  for (int i = 0; i < static_cast<int>(Kt.rows()); ++i) {
    const double lambda = a > 0 ? 1.0 / eig.eigenvalues()[i] - a : eig.eigenvalues()[i];
    RawMode mode;
    mode.s = lambda >= 0 ? std::complex<double>(0.0, std::sqrt(lambda)) : std::complex<double>(std::sqrt(-lambda), 0.0);
    mode.x = (T * eig.eigenvectors().col(i)).cast<std::complex<double>>();
    out.push_back(std::move(mode));
  }
  return out;
}

// Roots of the first-order form y' = A y, y = (q, q'/w), in time scaled by w (both blocks O(1)), from
// (A + k I)^{-1}, whose eigenvalues are 1 / (s/w + k), if k > 0, else directly.
std::vector<RawMode> FirstOrderRoots(const Eigen::MatrixXd& Kt, const Eigen::MatrixXd& Dt, const Eigen::MatrixXd& T,
                                     double w, double k) {
  const int r = static_cast<int>(Kt.rows());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * r, 2 * r);
  A.topRightCorner(r, r).setIdentity();
  A.bottomLeftCorner(r, r) = -Kt / (w * w);
  A.bottomRightCorner(r, r) = -Dt / w;
  if (k > 0) {
    A.diagonal().array() += k;
    A = Eigen::PartialPivLU<Eigen::MatrixXd>(A).inverse();
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(A, true);
  std::vector<RawMode> out;
  for (int i = 0; i < 2 * r; ++i) {
    RawMode mode;
    mode.s = k > 0 ? w * (1.0 / eig.eigenvalues()[i] - k) : w * eig.eigenvalues()[i];
    mode.x = T.cast<std::complex<double>>() * eig.eigenvectors().col(i).head(r);
    out.push_back(std::move(mode));
  }
  return out;
}

void SortByMagnitude(std::vector<RawMode>* roots) {
  std::sort(roots->begin(), roots->end(),
            [](const RawMode& a, const RawMode& b) { return std::abs(a.s) < std::abs(b.s); });
}

// The roots of `low` below `crossover` in |s|, then the largest of `high` to make up the count.
std::vector<RawMode> Merge(std::vector<RawMode> low, std::vector<RawMode> high, double crossover) {
  SortByMagnitude(&low);
  SortByMagnitude(&high);
  size_t n = 0;
  while (n < low.size() && std::abs(low[n].s) < crossover) ++n;
  std::vector<RawMode> out(std::make_move_iterator(low.begin()), std::make_move_iterator(low.begin() + n));
  out.insert(out.end(), std::make_move_iterator(high.begin() + n), std::make_move_iterator(high.end()));
  return out;
}
}  // namespace

EigenResult SolveDense(const Model& model, const LinearisedSystem& system, const EigenOptions& options) {
  const int nk = static_cast<int>(system.M.rows());
  const Eigen::MatrixXd K(system.K), D(system.D), M(system.M);
  const ConstraintNullSpace null_space(Eigen::MatrixXd(system.B), nk);
  const Eigen::MatrixXd& Z = null_space.Z();
  const int r = static_cast<int>(Z.cols());
  // T maps mass-normalised reduced coordinates to the kinematic unknowns: T^T M T = I.
  const Eigen::MatrixXd T = Z * MassNormalisingBasis(model, Z.transpose() * M * Z, Z);
  const Eigen::MatrixXd Kt = T.transpose() * K * T, Dt = T.transpose() * D * T;

  EigenResult result;
  result.method = "dense";
  result.num_kinematic = nk;
  result.num_dof = r;
  if (r == 0) return result;
  const double k_max = Kt.cwiseAbs().maxCoeff(), d_max = Dt.cwiseAbs().maxCoeff();
  const double asymmetry = (Kt - Kt.transpose()).cwiseAbs().maxCoeff();
  const bool symmetric = d_max == 0.0 && asymmetry <= kSymmetryTolerance * k_max;
  result.symmetric = symmetric;
  // Frequency scale of the model (its highest frequencies).
  double scale = std::max(std::sqrt(k_max), d_max);
  if (!(scale > 0)) scale = 1.0;
  const double crossover = std::sqrt(kShift) * scale;
  std::vector<RawMode> raw;
  if (symmetric) {
    const double a = (kShift * scale) * (kShift * scale);
    raw = Merge(SymmetricRoots(Kt, T, a), SymmetricRoots(Kt, T, 0.0), crossover);
  } else {
    raw = FirstOrderRoots(Kt, Dt, T, scale, kShift);
    // A rigid-body motion is a defective double root at 0 whose Jordan block, that close to the shift,
    // amplifies round-off by 1 / kShift^2 in the other roots: then the others all come from the direct
    // problem (dropping as many of its smallest roots as were rigid), whatever their size.
    std::vector<RawMode> rigid, elastic;
    for (RawMode& mode : raw)
      (IsRigidRoot(system, mode, scale, 0.0, options) ? rigid : elastic).push_back(std::move(mode));
    std::vector<RawMode> direct = FirstOrderRoots(Kt, Dt, T, scale, 0.0);
    if (rigid.empty()) {
      raw = Merge(std::move(elastic), std::move(direct), crossover);
    } else {
      SortByMagnitude(&direct);
      raw = std::move(rigid);
      raw.insert(raw.end(),
                 std::make_move_iterator(direct.begin() + static_cast<long>(std::min(raw.size(), direct.size()))),
                 std::make_move_iterator(direct.end()));
    }
  }
  ClassifyModes(system, raw, symmetric, scale, 0.0, options, &result);
  return result;
}

}  // namespace eigen_internal
}  // namespace flexmbd
