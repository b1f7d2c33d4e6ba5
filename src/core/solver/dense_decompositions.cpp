#include "dense_decompositions.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

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
