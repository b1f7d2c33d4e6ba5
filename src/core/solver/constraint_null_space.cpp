// Null space of a constraint Jacobian by a column-pivoted QR (docs/theory.md (E4)).

#include "constraint_null_space.hpp"

#include <Eigen/QR>

namespace flexmbd {
namespace {
// Pivots of the QR of B^T below this fraction of the largest are dependent constraint rows: redundant
// constraints give pivots at round-off (1e-16 relative); genuine ones differ by the ratio of lever arms.
constexpr double kRankTolerance = 1.0e-10;

// A Jacobian without a nonzero entry constrains nothing (the QR's relative threshold needs a largest pivot).
bool ConstrainsNothing(const Eigen::MatrixXd& B) { return B.size() == 0 || B.cwiseAbs().maxCoeff() == 0.0; }

// The column-pivoted QR of B^T with the rank threshold.
Eigen::ColPivHouseholderQR<Eigen::MatrixXd> PivotedQr(const Eigen::MatrixXd& B) {
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(B.transpose());
  qr.setThreshold(kRankTolerance);
  return qr;
}
}  // namespace

int ConstraintNullSpace::RankOf(const Eigen::MatrixXd& B) {
  return ConstrainsNothing(B) ? 0 : static_cast<int>(PivotedQr(B).rank());
}

ConstraintNullSpace::ConstraintNullSpace(const Eigen::MatrixXd& B, int num_kinematic) : n_(num_kinematic) {
  if (ConstrainsNothing(B)) {
    Z_ = Eigen::MatrixXd::Identity(n_, n_);
    Q1_.resize(n_, 0);
    return;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr = PivotedQr(B);
  rank_ = static_cast<int>(qr.rank());
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(n_, n_);
  Q1_ = Q.leftCols(rank_);
  Z_ = Q.rightCols(n_ - rank_);
  R1t_ = qr.matrixR().topLeftCorner(rank_, rank_).triangularView<Eigen::Upper>().toDenseMatrix().transpose();
  perm_ = qr.colsPermutation().indices();
}

Eigen::VectorXd ConstraintNullSpace::MinimumNormSolution(const Eigen::VectorXd& c) const {
  // B = P R^T Q^T; with x = Q1 y, B x = P R1^T y, whose leading rank rows are lower triangular.
  Eigen::VectorXd permuted(rank_);
  for (int i = 0; i < rank_; ++i) permuted[i] = c[perm_[i]];
  const Eigen::VectorXd y = R1t_.triangularView<Eigen::Lower>().solve(permuted);
  return Q1_ * y;
}

}  // namespace flexmbd
