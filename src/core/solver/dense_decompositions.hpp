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

/// The round-off of each eigenvalue of `matrix` (its eigenpairs `eig`): eps |A|_F times its condition number
/// |x| |y| / |y^H x| (y its left eigenvector), the first-order change of the eigenvalue under the solver's backward
/// error; infinite where the eigenvectors are dependent. A double root split by round-off into a pair ~sqrt(eps |A|)
/// apart has a condition number ~1 / its split, so its round-off covers the split. Meant for matrices scaled to
/// entries of order one: with entries of very different sizes the normwise error overstates the round-off.
Eigen::VectorXd EigenvalueRoundOff(const Eigen::MatrixXd& matrix, const Eigenpairs& eig);

/// Singular values in descending order and the thin left (U) or right (V) singular vectors.
struct SingularBasis {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};
SingularBasis LeftSingularBasis(const Eigen::MatrixXd& matrix);
SingularBasis RightSingularBasis(const Eigen::MatrixXd& matrix);

}  // namespace dense
}  // namespace flexmbd
