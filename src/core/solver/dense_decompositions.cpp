#include "dense_decompositions.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

namespace flexmbd {
namespace dense {

SymmetricEigenpairs SymmetricEigen(const Eigen::MatrixXd& symmetric) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(symmetric);
  return {eig.eigenvalues(), eig.eigenvectors()};
}

Eigenpairs GeneralEigen(const Eigen::MatrixXd& matrix) {
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(matrix, true);
  return {eig.eigenvalues(), eig.eigenvectors()};
}

Eigen::VectorXd EigenvalueRoundOff(const Eigen::MatrixXd& matrix, const Eigenpairs& eig) {
  // The rows of V^-1 are the left eigenvectors scaled to y^H x = 1. An exactly defective V has no inverse: its
  // eigenvalues are not resolved at all.
  const Eigen::MatrixXcd left = Eigen::PartialPivLU<Eigen::MatrixXcd>(eig.vectors).inverse();
  const double backward_error = Eigen::NumTraits<double>::epsilon() * matrix.norm();
  Eigen::VectorXd round_off(eig.values.size());
  for (Eigen::Index i = 0; i < eig.values.size(); ++i) {
    const double condition = eig.vectors.col(i).norm() * left.row(i).norm();
    round_off[i] = std::isfinite(condition) ? backward_error * condition : std::numeric_limits<double>::infinity();
  }
  return round_off;
}

SingularBasis LeftSingularBasis(const Eigen::MatrixXd& matrix) {
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(matrix, Eigen::ComputeThinU);
  return {svd.singularValues(), svd.matrixU()};
}

SingularBasis RightSingularBasis(const Eigen::MatrixXd& matrix) {
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(matrix, Eigen::ComputeThinV);
  return {svd.singularValues(), svd.matrixV()};
}

}  // namespace dense
}  // namespace flexmbd
