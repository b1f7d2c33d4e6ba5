// Sparse eigen-solution for large models (docs/theory.md, eq. (E6)): shift-invert Arnoldi on the
// first-order form of the constrained quadratic pencil, each operator application one solve with the KLU
// factorisation of [K + sigma D + sigma^2 M, B^T; B, 0].

#include <klu.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>

#include "eigen_internal.hpp"
#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace eigen_internal {

using Complex = std::complex<double>;

struct KluLu::Data {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  bool complex = false;
  int n = 0;
  std::vector<int> column_start, row_index;
  std::vector<double> values;  ///< interleaved (re, im) when complex

  void Free() {
    if (numeric) complex ? klu_z_free_numeric(&numeric, &common) : klu_free_numeric(&numeric, &common);
    if (symbolic) klu_free_symbolic(&symbolic, &common);
  }
};

KluLu::KluLu() : data_(std::make_unique<Data>()) { klu_defaults(&data_->common); }

KluLu::~KluLu() { data_->Free(); }

bool KluLu::Factorise(const Eigen::SparseMatrix<double>& A) {
  data_->Free();
  data_->complex = false;
  Eigen::SparseMatrix<double> c = A;
  c.makeCompressed();
  Data& d = *data_;
  d.n = static_cast<int>(c.rows());
  d.column_start.assign(c.outerIndexPtr(), c.outerIndexPtr() + d.n + 1);
  d.row_index.assign(c.innerIndexPtr(), c.innerIndexPtr() + c.nonZeros());
  d.values.assign(c.valuePtr(), c.valuePtr() + c.nonZeros());
  d.symbolic = klu_analyze(d.n, d.column_start.data(), d.row_index.data(), &d.common);
  if (!d.symbolic) return false;
  d.numeric = klu_factor(d.column_start.data(), d.row_index.data(), d.values.data(), d.symbolic, &d.common);
  return d.numeric != nullptr && d.common.status == KLU_OK;
}

bool KluLu::Factorise(const Eigen::SparseMatrix<std::complex<double>>& A) {
  data_->Free();
  data_->complex = true;
  Eigen::SparseMatrix<Complex> c = A;
  c.makeCompressed();
  Data& d = *data_;
  d.n = static_cast<int>(c.rows());
  d.column_start.assign(c.outerIndexPtr(), c.outerIndexPtr() + d.n + 1);
  d.row_index.assign(c.innerIndexPtr(), c.innerIndexPtr() + c.nonZeros());
  d.values.resize(2 * c.nonZeros());
  for (int k = 0; k < c.nonZeros(); ++k) {
    d.values[2 * k] = c.valuePtr()[k].real();
    d.values[2 * k + 1] = c.valuePtr()[k].imag();
  }
  d.symbolic = klu_analyze(d.n, d.column_start.data(), d.row_index.data(), &d.common);
  if (!d.symbolic) return false;
  d.numeric = klu_z_factor(d.column_start.data(), d.row_index.data(), d.values.data(), d.symbolic, &d.common);
  return d.numeric != nullptr && d.common.status == KLU_OK;
}

bool KluLu::Solve(Eigen::VectorXd* b) const {
  Data& d = *data_;
  if (!d.numeric || d.complex) return false;
  return klu_solve(d.symbolic, d.numeric, d.n, 1, b->data(), &d.common) && b->allFinite();
}

bool KluLu::Solve(Eigen::VectorXcd* b) const {
  Data& d = *data_;
  if (!d.numeric || !d.complex) return false;
  return klu_z_solve(d.symbolic, d.numeric, d.n, 1, reinterpret_cast<double*>(b->data()), &d.common) && b->allFinite();
}

double KluLu::rcond() const {
  Data& d = *data_;
  if (!d.numeric) return 0.0;
  const int ok =
      d.complex ? klu_z_rcond(d.symbolic, d.numeric, &d.common) : klu_rcond(d.symbolic, d.numeric, &d.common);
  return ok ? d.common.rcond : 0.0;
}

namespace {
// Modes reported by the sparse method when the options ask for all of them.
constexpr int kDefaultSparseModes = 10;
// Ritz pairs are accepted when their residual estimate is below this fraction of their magnitude.
constexpr double kRitzTolerance = 1.0e-10;
// Largest Krylov space, as a multiple of the roots sought (plus a margin); the space is extended until the
// roots converge or it is reached.
constexpr int kKrylovFactor = 8, kKrylovMargin = 40;
// The shift sigma stands this fraction of the frequency scale sqrt(max K_ii / M_ii) to the left of the
// imaginary axis, so that K + sigma D + sigma^2 M stays regular with rigid-body modes or an undamped mode at
// the target, while the lowest roots of stiff models (1e-7 of the scale and up) stay far from it.
constexpr double kShiftOffset = 1.0e-8;
// Rigid-body roots found with that shift: a defective double root at 0 perturbed by round-off amplified by the
// Jordan block, so |s| up to a small fraction of the offset; genuine roots that low are rigid in practice.
constexpr double kRigidFractionOfOffset = 1.0e-2;
// With the second shift the amplification is harmless and rigid-body roots come out at ~1e-8 of it.
constexpr double kRigidFractionOfSecondOffset = 1.0e-6;
// With rigid-body modes the shift stands this fraction of the lowest elastic frequency off the axis: the
// defective zero root then amplifies round-off by only (1 / 0.05)^2 = 400 per step, and the lowest roots stay
// well separated in the shift-inverted spectrum.
constexpr double kRigidShiftFraction = 0.05;
// Arnoldi breakdown: the new Krylov vector is below this fraction of its projections (an invariant subspace).
constexpr double kBreakdown = 1.0e-14;

// sqrt(max over unknowns with mass of K_ii / M_ii): the highest frequency scale of the model [rad/s].
double FrequencyScale(const LinearisedSystem& system) {
  double largest = 0;
  const Eigen::VectorXd k = system.K.diagonal(), m = system.M.diagonal();
  for (int i = 0; i < k.size(); ++i) {
    if (m[i] > 0 && k[i] > 0) largest = std::max(largest, k[i] / m[i]);
  }
  return largest > 0 ? std::sqrt(largest) : 1.0;
}

// The operator (A - sigma E)^{-1} E of the first-order form on z = (x, x'), theory (E6).
class ShiftInvert {
 public:
  ShiftInvert(const LinearisedSystem& system, Complex sigma) : system_(system), sigma_(sigma) {
    const int nk = static_cast<int>(system.M.rows()), m = static_cast<int>(system.B.rows());
    nk_ = nk;
    m_ = m;
    using Triplet = Eigen::Triplet<Complex>;
    std::vector<Triplet> t;
    auto add = [&](const Eigen::SparseMatrix<double>& A, Complex factor, int row0, int col0, bool transpose) {
      for (int j = 0; j < A.outerSize(); ++j) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
          const int row = transpose ? j : static_cast<int>(it.row()), col = transpose ? static_cast<int>(it.row()) : j;
          t.emplace_back(row0 + row, col0 + col, factor * it.value());
        }
      }
    };
    add(system.K, 1.0, 0, 0, false);
    add(system.D, sigma, 0, 0, false);
    add(system.M, sigma * sigma, 0, 0, false);
    add(system.B, 1.0, nk, 0, false);
    add(system.B, 1.0, 0, nk, true);
    Eigen::SparseMatrix<Complex> A(nk + m, nk + m);
    A.setFromTriplets(t.begin(), t.end());
    if (!lu_.Factorise(A)) {
      std::ostringstream msg;
      msg << "eigen-analysis: the shifted matrix [K + s D + s^2 M, B^T; B, 0] at s = " << sigma
          << " 1/s is singular (redundant constraints, or s is an eigenvalue: choose another shift)";
      throw SolverError(msg.str());
    }
  }

  Eigen::VectorXcd Apply(const Eigen::VectorXcd& z) const {
    const Eigen::VectorXcd v1 = z.head(nk_), v2 = z.tail(nk_);
    Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(nk_ + m_);
    rhs.head(nk_) = -(Multiply(system_.M, v2) + Multiply(system_.D, v1) + sigma_ * Multiply(system_.M, v1));
    if (!lu_.Solve(&rhs)) throw SolverError("eigen-analysis: the shift-invert solve failed (non-finite result)");
    Eigen::VectorXcd w(2 * nk_);
    w.head(nk_) = rhs.head(nk_);
    w.tail(nk_) = v1 + sigma_ * rhs.head(nk_);
    return w;
  }

 private:
  static Eigen::VectorXcd Multiply(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXcd& x) {
    const Eigen::VectorXd re = A * x.real(), im = A * x.imag();
    return re.cast<Complex>() + Complex(0, 1) * im.cast<Complex>();
  }

  const LinearisedSystem& system_;
  Complex sigma_;
  int nk_ = 0, m_ = 0;
  KluLu lu_;
};
// The `wanted` roots nearest sigma by Arnoldi on the shift-invert operator, extended until their Ritz
// residuals converge or the Krylov space reaches max_krylov vectors.
std::vector<RawMode> NearestRoots(const LinearisedSystem& system, Complex sigma, int wanted, int max_krylov) {
  const int nk = static_cast<int>(system.M.rows());
  const ShiftInvert op(system, sigma);
  // Start vectors: pseudo-random vectors mapped once by the operator, with the velocity half set to zero: both
  // halves then satisfy B x = 0 (the operator's invariant space) and no component is amplified by more than one
  // application.
  auto start = [&](int seed) -> Eigen::VectorXcd {
    Eigen::VectorXcd v(2 * nk);
    for (int i = 0; i < 2 * nk; ++i)
      v[i] = Complex(std::sin(1.0 + 7.0 * i + seed), std::cos(3.0 + 11.0 * i + 5.0 * seed));
    v = op.Apply(v);
    v.tail(nk).setZero();
    return v;
  };
  Eigen::MatrixXcd V(2 * nk, max_krylov + 1);
  Eigen::MatrixXcd H = Eigen::MatrixXcd::Zero(max_krylov + 1, max_krylov);
  V.col(0) = start(0).normalized();
  int k = 0, restarts = 0;
  Eigen::VectorXcd ritz;
  Eigen::MatrixXcd vectors;
  std::vector<int> order;
  bool converged = false, exhausted = false;
  while (k < max_krylov && !converged && !exhausted) {
    // Arnoldi step with two passes of classical Gram-Schmidt.
    Eigen::VectorXcd w = op.Apply(V.col(k));
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXcd h = V.leftCols(k + 1).adjoint() * w;
      w -= V.leftCols(k + 1) * h;
      H.col(k).head(k + 1) += h;
    }
    double beta = w.norm();
    ++k;
    if (beta <= kBreakdown * H.col(k - 1).head(k).norm()) {
      // The space is invariant (a shift at a root gives this at once): go on from a fresh start vector.
      beta = 0;
      Eigen::VectorXcd fresh = start(++restarts);
      const double size = fresh.norm();
      for (int pass = 0; pass < 2; ++pass) fresh -= V.leftCols(k) * (V.leftCols(k).adjoint() * fresh);
      exhausted = fresh.norm() <= kBreakdown * size;
      if (!exhausted) V.col(k) = fresh.normalized();
    } else {
      V.col(k) = w / beta;
    }
    H(k, k - 1) = beta;
    if (k < wanted && !exhausted) continue;
    const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> eig(H.topLeftCorner(k, k));
    ritz = eig.eigenvalues();
    vectors = eig.eigenvectors();
    order.resize(k);
    for (int i = 0; i < k; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(ritz[a]) > std::abs(ritz[b]); });
    converged = true;
    for (int i = 0; i < std::min(wanted, k); ++i) {
      const int j = order[i];
      const double residual = beta * std::abs(vectors(k - 1, j)) / vectors.col(j).norm();
      if (residual > kRitzTolerance * std::abs(ritz[j])) converged = false;
    }
  }
  if (!converged) {
    std::ostringstream msg;
    msg << "eigen-analysis: shift-invert Arnoldi did not converge in " << k << " Krylov vectors for " << wanted
        << " roots near s = " << sigma << " 1/s";
    throw SolverError(msg.str());
  }
  // Round-off of each Ritz value mu: its condition number in H (from H's left eigenvectors, the rows of the
  // inverse of its eigenvectors) times its residual and the round-off of H (theory (E6)).
  const Eigen::MatrixXcd left = Eigen::PartialPivLU<Eigen::MatrixXcd>(vectors).inverse();
  const double backward_error = Eigen::NumTraits<double>::epsilon() * H.topLeftCorner(k, k).norm();
  std::vector<RawMode> raw;
  for (int i = 0; i < std::min(wanted, k); ++i) {
    const int j = order[i];
    if (std::abs(ritz[j]) == 0.0) continue;
    RawMode mode;
    mode.s = sigma + 1.0 / ritz[j];
    mode.x = (V.leftCols(k) * vectors.col(j)).head(nk);
    const double residual = std::abs(H(k, k - 1)) * std::abs(vectors(k - 1, j)) / vectors.col(j).norm();
    const double condition = vectors.col(j).norm() * left.row(j).norm();
    // A change d of mu = 1 / (s - sigma) moves s by d / |mu|^2; a condition number that is not finite (an exactly
    // defective H) leaves the root unresolved.
    mode.round_off = std::isfinite(condition) ? condition * (residual + backward_error) / std::norm(ritz[j])
                                              : std::numeric_limits<double>::infinity();
    raw.push_back(std::move(mode));
  }
  return raw;
}
}  // namespace

namespace {
// Keeps the `count` modes whose frequencies lie nearest `target_hz`, in order of frequency.
void KeepNearest(double target_hz, int count, EigenResult* result) {
  std::vector<Mode>& modes = result->modes;
  if (static_cast<int>(modes.size()) <= count) return;
  std::stable_sort(modes.begin(), modes.end(), [&](const Mode& a, const Mode& b) {
    return std::abs(a.frequency_hz - target_hz) < std::abs(b.frequency_hz - target_hz);
  });
  modes.resize(count);
  std::stable_sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) {
    if (a.rigid_body != b.rigid_body) return a.rigid_body;
    return a.frequency_hz < b.frequency_hz;
  });
  result->num_rigid_body =
      static_cast<int>(std::count_if(modes.begin(), modes.end(), [](const Mode& m) { return m.rigid_body; }));
}
}  // namespace

EigenResult SolveSparse(const Model& model, const LinearisedSystem& system, const EigenOptions& options) {
  const int nk = static_cast<int>(system.M.rows()), m = static_cast<int>(system.B.rows());
  const int num_modes = options.num_modes > 0 ? options.num_modes : kDefaultSparseModes;
  const double scale = FrequencyScale(system);
  const int dimension = 2 * std::max(nk - m, 0);
  // Roots sought: both of each conjugate pair may lie near a real shift.
  const int wanted = std::min(2 * num_modes, dimension);
  const int max_krylov = std::min(kKrylovFactor * wanted + kKrylovMargin, dimension);
  // When the Krylov space would have to span (nearly) the whole constrained space, the dense method is both
  // cheaper and exact in every root.
  if (kKrylovFactor * wanted + kKrylovMargin >= dimension) {
    EigenOptions all = options;
    all.num_modes = 0;
    EigenResult result = SolveDense(model, system, all);
    KeepNearest(options.shift_hz, num_modes, &result);
    return result;
  }
  EigenResult result;
  result.method = "sparse shift-invert";
  result.num_kinematic = nk;
  result.num_dof = nk - m;
  if (wanted == 0) return result;
  // Modes are cut to those nearest the target after classification (all roots found are kept until then).
  EigenOptions all = options;
  all.num_modes = 0;
  const double target = 2 * M_PI * options.shift_hz;
  const double offset = kShiftOffset * scale;
  // A rigid-body root comes out within a small fraction of this offset from 0 (below: with the second shift).
  ClassifyModes(model, system, NearestRoots(system, Complex(-offset, target), wanted, max_krylov), false, 0, scale,
                kRigidFractionOfOffset * offset, all, &result);
  if (result.num_rigid_body > 0) {
    // A rigid-body motion is a defective double root at 0: with the shift that close, its Jordan block
    // amplifies round-off by (frequency / offset)^2 in every Arnoldi step. Solve again with the shift a
    // fraction of the lowest elastic frequency away from the axis, where the amplification is harmless.
    double lowest = scale;
    for (const Mode& mode : result.modes) {
      if (!mode.rigid_body) lowest = std::min(lowest, 2 * M_PI * mode.frequency_hz);
    }
    const double second = kRigidShiftFraction * lowest;
    ClassifyModes(model, system, NearestRoots(system, Complex(-second, target), wanted, max_krylov), false, 0, scale,
                  kRigidFractionOfSecondOffset * second, all, &result);
  }
  KeepNearest(options.shift_hz, num_modes, &result);
  return result;
}

}  // namespace eigen_internal
}  // namespace flexmbd
