#pragma once
/// @file
/// Makes the discrete gradient of a joint's rotation rows blind to a rigid rotation of both its sides, so that
/// the torques G^T lambda it applies to the two nodes sum to zero and conserve angular momentum (docs/theory.md,
/// "Angular momentum of joint torques").

#include <Eigen/Core>

#include "flexmbd/math/so3.hpp"

namespace flexmbd {

/// The step's increments that the rotation rows depend on, in one compact space: the parent's and the child's
/// rotation increments theta (node frames at i) and the joint's rotation variables.
struct RotationIncrements {
  static constexpr int kMax = 9;  ///< two nodes and up to three rotation variables
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;
  using Generators = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMax, 3>;
  using Rows = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMax>;

  Vector z;           ///< the increments themselves
  Generators delta;   ///< column k: a rigid rotation of both sides about W axis k (theta = R_i^T e_k, variables 0)
};

/// The least change M of the rows' discrete gradient G (3 x increments) with M z = 0 and (G - M) delta = 0:
/// M = [G delta, 0] (X^T X)^+ X^T, X = [delta, z/|z|]. G - M keeps G z = Phi_f - Phi_i (the forces' work) and
/// balances the torques exactly. Directions of X^T X below 1e-12 of its largest (z in the span of delta: a step
/// that turns both sides together, where G delta is a multiple of Phi_f - Phi_i) are left out.
class RigidRotationBalance {
 public:
  RigidRotationBalance(const RotationIncrements& increments, const RotationIncrements::Rows& G);

  /// G - M.
  RotationIncrements::Rows Balanced() const;
  /// The variation of G - M along increment `l` (-1: one that moves neither z nor delta), given G's, dG.
  RotationIncrements::Rows BalancedVariation(const RotationIncrements::Rows& dG, int l) const;

 private:
  using Frame = Eigen::Matrix<double, Eigen::Dynamic, 4, 0, RotationIncrements::kMax, 4>;
  using Matrix4 = Eigen::Matrix<double, 4, 4>;
  RotationIncrements increments_;
  RotationIncrements::Rows G_;
  double z_norm_ = 0;
  Frame X_;                      // [delta, z/|z|] (the last column zero when z is)
  Matrix4 A_inverse_;            // (X^T X)^+
  Eigen::Matrix<double, 3, 4> targets_;  // [G delta, 0]
};

}  // namespace flexmbd
