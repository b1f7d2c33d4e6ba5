// Dense eigen-solution of a linearised system (docs/theory.md, eqs. (E4)-(E5)): null-space elimination of
// the constraints, mass normalisation, and either the symmetric problem (no damping or gyroscopic terms,
// symmetric stiffness) or the first-order state-space problem.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iterator>

#include "dense_decompositions.hpp"
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
// A direction engages neither stiffness nor damping when its singular value of [Kt; w Dt] is below this
// fraction of the largest: round-off is ~eps sqrt(r) (1e-15 at r = 2000); the lowest elastic modes of stiff
// finite-element models stay above 1e-12 (the flexible antenna's: 9e-12), as in IsRigidRoot's kCancellation.
constexpr double kRigidCancellation = 1.0e-14;

// Roots of the symmetric problem Kt v = omega^2 v, from (Kt + a I)^{-1} if a > 0, else directly.
std::vector<RawMode> SymmetricRoots(const Eigen::MatrixXd& Kt, const Eigen::MatrixXd& T, double a) {
  Eigen::MatrixXd matrix = 0.5 * (Kt + Kt.transpose());
  if (a > 0) {
    matrix.diagonal().array() += a;
    matrix = Eigen::PartialPivLU<Eigen::MatrixXd>(matrix).inverse();
  }
  const dense::SymmetricEigenpairs eig = dense::SymmetricEigen(0.5 * (matrix + matrix.transpose()));
  std::vector<RawMode> out;
  for (int i = 0; i < static_cast<int>(Kt.rows()); ++i) {
    const double lambda = a > 0 ? 1.0 / eig.values[i] - a : eig.values[i];
    RawMode mode;
    mode.s = lambda >= 0 ? std::complex<double>(0.0, std::sqrt(lambda)) : std::complex<double>(std::sqrt(-lambda), 0.0);
    mode.x = (T * eig.vectors.col(i)).cast<std::complex<double>>();
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

// Roots of the first-order form y' = A y, y = (q, q'/w), in time scaled by w (both blocks O(1)), from
// (A + k I)^{-1}, whose eigenvalues are 1 / (s/w + k), if k > 0, else directly. Shapes in the coordinates of
// Kt and Dt.
std::vector<RawMode> FirstOrderRoots(const Eigen::MatrixXd& Kt, const Eigen::MatrixXd& Dt, double w, double k) {
  const int r = static_cast<int>(Kt.rows());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * r, 2 * r);
  A.topRightCorner(r, r).setIdentity();
  A.bottomLeftCorner(r, r) = -Kt / (w * w);
  A.bottomRightCorner(r, r) = -Dt / w;
  if (k > 0) {
    A.diagonal().array() += k;
    A = Eigen::PartialPivLU<Eigen::MatrixXd>(A).inverse();
  }
  const dense::Eigenpairs eig = dense::GeneralEigen(A);
  const Eigen::VectorXd round_off = dense::EigenvalueRoundOff(A, eig);
  std::vector<RawMode> out;
  for (int i = 0; i < 2 * r; ++i) {
    RawMode mode;
    mode.s = k > 0 ? w * (1.0 / eig.values[i] - k) : w * eig.values[i];
    mode.x = eig.vectors.col(i).head(r);
    // A change d of the inverted eigenvalue mu moves s by w d / |mu|^2.
    mode.round_off = k > 0 ? w * round_off[i] / std::norm(eig.values[i]) : w * round_off[i];
    out.push_back(std::move(mode));
  }
  return out;
}

// The rigid-body motions of the mass-normalised problem: an orthonormal basis N of the directions that neither
// stiffness nor damping engages (Kt N = Dt N = 0 to round-off), and Q of the rest (theory (E5)).
struct RigidSplit {
  Eigen::MatrixXd N, Q;
};

RigidSplit SplitRigidMotions(const Eigen::MatrixXd& Kt, const Eigen::MatrixXd& Dt, double w) {
  const int r = static_cast<int>(Kt.rows());
  Eigen::MatrixXd stacked(2 * r, r);
  stacked << Kt, w * Dt;
  const dense::SingularBasis svd = dense::RightSingularBasis(stacked);
  const Eigen::VectorXd& sigma = svd.values;
  int engaged = 0;
  while (engaged < r && sigma[engaged] > kRigidCancellation * sigma[0]) ++engaged;
  return {svd.vectors.rightCols(r - engaged), svd.vectors.leftCols(engaged)};
}

// The roots of the first-order problem without its rigid-body motions: those of the problem restricted to Q,
// whose shapes y = Q b + N a take a = -N^T (s Dt + Kt) Q b / s^2 from the rows along N; then a double root at
// zero per rigid motion. Restricted to Q, no defective root at zero is left near the shift, so every root comes
// from the shifted inverse below the crossover and from the direct problem above it.
std::vector<RawMode> FirstOrderRootsWithoutRigidMotions(const Eigen::MatrixXd& Kt, const Eigen::MatrixXd& Dt,
                                                        const Eigen::MatrixXd& T, double w, double crossover) {
  const RigidSplit split = SplitRigidMotions(Kt, Dt, w);
  const Eigen::MatrixXd& Q = split.Q;
  const Eigen::MatrixXd& N = split.N;
  std::vector<RawMode> roots;
  if (Q.cols() > 0) {
    const Eigen::MatrixXd Kq = Q.transpose() * Kt * Q, Dq = Q.transpose() * Dt * Q;
    roots = Merge(FirstOrderRoots(Kq, Dq, w, kShift), FirstOrderRoots(Kq, Dq, w, 0.0), crossover);
  }
  // The blocks of Kt and Dt that couple the rigid motions to the rest give a; each shape is then mapped to the
  // unknowns once.
  using Complex = std::complex<double>;
  const Eigen::MatrixXcd NKQ = (N.transpose() * Kt * Q).cast<Complex>(), NDQ = (N.transpose() * Dt * Q).cast<Complex>();
  const Eigen::MatrixXcd Qc = Q.cast<Complex>(), Nc = N.cast<Complex>(), Tc = T.cast<Complex>();
  for (RawMode& mode : roots) {
    const Eigen::VectorXcd& b = mode.x;
    const Eigen::VectorXcd a = -(mode.s * (NDQ * b) + NKQ * b) / (mode.s * mode.s);
    mode.x = Tc * (Qc * b + Nc * a);
  }
  for (int i = 0; i < N.cols(); ++i) {
    const RawMode rigid{0.0, (T * N.col(i)).cast<std::complex<double>>()};
    roots.push_back(rigid);
    roots.push_back(rigid);
  }
  return roots;
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
  // Frequency scale of the model: its highest frequencies (without stiffness, its fastest decay). The
  // first-order form is scaled by it and the rigid-body tolerance is relative to it. A fast decay mu w^2 of
  // overdamped stiff modes is no frequency: scaled by that (6e9 rad/s against 3e6 for the beam of
  // BeamDamping.HingedBeamAtDefaultEigenSettingsKeepsItsLowestModesExact), the lowest roots lost 4% on the
  // flexible antenna and fell below the rigid-body tolerance.
  double scale = k_max > 0.0 ? std::sqrt(k_max) : d_max;
  if (!(scale > 0)) scale = 1.0;
  const double crossover = std::sqrt(kShift) * scale;
  std::vector<RawMode> raw;
  if (symmetric) {
    const double a = (kShift * scale) * (kShift * scale);
    raw = Merge(SymmetricRoots(Kt, T, a), SymmetricRoots(Kt, T, 0.0), crossover);
  } else {
    raw = FirstOrderRootsWithoutRigidMotions(Kt, Dt, T, scale, crossover);
  }
  ClassifyModes(model, system, raw, symmetric, 0, scale, options.rigid_tolerance * scale, options, &result);
  return result;
}

}  // namespace eigen_internal
}  // namespace flexmbd
