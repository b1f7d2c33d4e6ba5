#pragma once
/// @file
/// The matrices of Peters' finite-state induced-flow model of a two-dimensional airfoil (Peters, Karunamoorthy
/// and Cao 1995; docs/theory.md, (A1)): N states lambda with
///   Abar lambda' + (U/b) lambda = cbar (w0' + w1'/2),   lambda0 = (1/2) bbar^T lambda.

#include <Eigen/Core>

namespace flexmbd {

struct PetersInflow {
  /// The model with N >= 0 states (N = 0: no wake lag, the quasi-steady limit lambda0 = 0).
  explicit PetersInflow(int num_states);
  Eigen::MatrixXd A;  ///< Abar = Dbar + dbar bbar^T + cbar dbar^T + cbar bbar^T / 2 (N x N)
  Eigen::VectorXd b;  ///< bbar: lambda0 = b^T lambda / 2
  Eigen::VectorXd c;  ///< cbar_n = 2 / n
};

}  // namespace flexmbd
