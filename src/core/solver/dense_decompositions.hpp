#pragma once
// The dense eigen- and singular-value decompositions the eigen-analysis takes, behind plain functions: each of
// Eigen's solvers is compiled once, in dense_decompositions.cpp, instead of in every file that calls it (BDCSVD
// alone costs about 25 s of compile time per file that instantiates it).

#include <Eigen/Core>

namespace flexmbd {
namespace dense {

/// Eigenvalues in ascending order and orthonormal eigenvectors (columns) of a symmetric matrix.
struct SymmetricEigenpairs {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};
SymmetricEigenpairs SymmetricEigen(const Eigen::MatrixXd& symmetric);

/// Eigenvalues and eigenvectors (columns) of a general real matrix, in the solver's order.
struct Eigenpairs {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
};
Eigenpairs GeneralEigen(const Eigen::MatrixXd& matrix);

/// Singular values in descending order and the thin left (U) or right (V) singular vectors.
struct SingularBasis {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};
SingularBasis LeftSingularBasis(const Eigen::MatrixXd& matrix);
SingularBasis RightSingularBasis(const Eigen::MatrixXd& matrix);

}  // namespace dense
}  // namespace flexmbd
