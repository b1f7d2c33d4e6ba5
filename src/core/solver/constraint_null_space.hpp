#pragma once
// Null space and rank of a constraint Jacobian, shared by the eigen-analysis (docs/theory.md (E4)) and the test
// for sticking rows that repeat other constraints (docs/theory.md (F7)).

#include <Eigen/Core>

namespace flexmbd {

/// Null space of the constraint Jacobian B (m x n) from a column-pivoted QR of B^T = Q R P^T: the first
/// `rank` columns of Q span the range of B^T, the others (Z) the motions that keep the constraints. Pivots below
/// 1e-10 of the largest count as dependent rows.
class ConstraintNullSpace {
 public:
  ConstraintNullSpace(const Eigen::MatrixXd& B, int num_kinematic);
  /// The rank of B by the same QR and pivot rule, without forming Q (the test for repeated rows needs only it).
  static int RankOf(const Eigen::MatrixXd& B);
  const Eigen::MatrixXd& Z() const { return Z_; }
  int rank() const { return rank_; }
  /// The smallest-norm x with B x = c (c consistent with B when rows of B are dependent).
  Eigen::VectorXd MinimumNormSolution(const Eigen::VectorXd& c) const;

 private:
  int n_ = 0, rank_ = 0;
  Eigen::MatrixXd Z_;
  Eigen::MatrixXd Q1_;    ///< range of B^T (n x rank)
  Eigen::MatrixXd R1t_;   ///< leading rank x rank block of R, transposed (lower triangular)
  Eigen::VectorXi perm_;  ///< column permutation of B^T: B^T P
};

}  // namespace flexmbd
