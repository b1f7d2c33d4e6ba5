#pragma once
/// @file
/// The matrices of Peters' finite-state induced-flow model of a two-dimensional airfoil (Peters, Karunamoorthy
/// and Cao 1995; docs/theory.md, (A1)): N states lambda with
///   Abar lambda' + (U/b) lambda = cbar (w0' + w1'/2),   lambda0 = (1/2) bbar^T lambda.

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace flexmbd {

struct PetersInflow {
  /// The model with N >= 0 states (N = 0: no wake lag, the quasi-steady limit lambda0 = 0).
  explicit PetersInflow(int num_states);
  Eigen::MatrixXd A;  ///< Abar = Dbar + dbar bbar^T + cbar dbar^T + cbar bbar^T / 2 (N x N)
  Eigen::VectorXd b;  ///< bbar: lambda0 = b^T lambda / 2
  Eigen::VectorXd c;  ///< cbar_n = 2 / n
};

/// The size [m/s] at which the local error test measures the Peters states of an airfoil in air of speed `air_speed`
/// [m/s] (Element::StateScale): the air speed, which scales the downwash the states carry, but at least 1 m/s. In
/// still air the states' equations lose their time scale b/U: they stay at rest, or move by the chordwise speed of
/// the airfoil's own motion and by round-off, and against a floor of 0 their relative error was noise (a still-air
/// strip stopped below dt_min at t = 2e-7 s, a section's 0/0 switched the step control off).
inline double PetersStateScale(double air_speed) { return std::max(std::abs(air_speed), 1.0); }

}  // namespace flexmbd
