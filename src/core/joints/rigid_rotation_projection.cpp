#include "flexmbd/joints/rigid_rotation_projection.hpp"

#include <Eigen/Eigenvalues>

namespace flexmbd {
namespace {
// Directions of X^T X below this fraction of its largest eigenvalue are left out (its columns are unit-sized:
// the generators have length sqrt(2), z is normalised).
constexpr double kRankFloor = 1.0e-12;
}  // namespace

RigidRotationBalance::RigidRotationBalance(const RotationIncrements& increments, const RotationIncrements::Rows& G)
    : increments_(increments), G_(G) {
  const int m = static_cast<int>(increments.z.size());
  z_norm_ = increments.z.norm();
  X_.setZero(m, 4);
  X_.leftCols<3>() = increments.delta;
  if (z_norm_ > 0) X_.col(3) = increments.z / z_norm_;
  const Eigen::SelfAdjointEigenSolver<Matrix4> eigen(X_.transpose() * X_);
  const double floor = kRankFloor * eigen.eigenvalues().maxCoeff();
  A_inverse_.setZero();
  for (int k = 0; k < 4; ++k) {
    const double value = eigen.eigenvalues()[k];
    if (value > floor) A_inverse_ += eigen.eigenvectors().col(k) * eigen.eigenvectors().col(k).transpose() / value;
  }
  targets_.setZero();
  targets_.leftCols<3>() = G * increments.delta;
}

RotationIncrements::Rows RigidRotationBalance::Balanced() const {
  return G_ - targets_ * A_inverse_ * X_.transpose();
}

RotationIncrements::Rows RigidRotationBalance::BalancedVariation(const RotationIncrements::Rows& dG, int l) const {
  Eigen::Matrix<double, 3, 4> d_targets = Eigen::Matrix<double, 3, 4>::Zero();
  d_targets.leftCols<3>() = dG * increments_.delta;
  RotationIncrements::Rows variation = dG - d_targets * A_inverse_ * X_.transpose();
  if (l < 0 || z_norm_ == 0) return variation;
  // X's last column z/|z| moves along increment l: (e_l - zhat zhat_l)/|z|; delta does not.
  Frame dX = Frame::Zero(X_.rows(), 4);
  dX.col(3) = -X_.col(3) * X_(l, 3);
  dX(l, 3) += 1.0;
  dX.col(3) /= z_norm_;
  const Matrix4 dA = dX.transpose() * X_ + X_.transpose() * dX;
  // d(A^+ X^T) = -A^+ dA A^+ X^T + A^+ dX^T on the range A^+ keeps.
  variation -= targets_ * (A_inverse_ * dX.transpose() - A_inverse_ * dA * A_inverse_ * X_.transpose());
  return variation;
}

}  // namespace flexmbd
