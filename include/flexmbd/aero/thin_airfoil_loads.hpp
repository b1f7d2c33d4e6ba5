#pragma once
/// @file
/// Unsteady thin-airfoil loads of a section in plunge h (down), pitch alpha (nose up, about the elastic axis at
/// a b aft of mid-chord) and trailing-edge flap delta (trailing edge down, hinged at c b aft of mid-chord), as
/// generalised forces work-conjugate to q = (h, alpha, delta) (docs/theory.md, (A2)-(A5)):
///   Q = -rho [Ma q'' + U Cnc q' + U^2 Knc q] - 2 pi rho U b [es (ew^T q' + U eg^T q) - ef lambda0].
/// Ma, Cnc, Knc project the pressure of the acyclic (non-circulatory) flow on the deformation shapes of the three
/// coordinates, es the Kutta (1/sqrt(b^2 - x^2)) loading of the three-quarter-chord downwash, ef the flat-plate
/// loading of the wake's inflow lambda0; the downwash driving Peters' inflow (A1) is
/// w0' + w1'/2 = ew^T q'' + U eg^T q'.

#include <Eigen/Core>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

struct ThinAirfoilLoads {
  /// Semichord b > 0 [m]; elastic axis a and hinge c in semichords aft of mid-chord, -1 <= a <= 1, -1 < c < 1.
  ThinAirfoilLoads(double semichord, double a, double c);
  /// The generalised forces Q for air density rho [kg/m^3], speed U [m/s] and inflow lambda0 [m/s], per span.
  Vec3 Forces(double rho, double U, const Vec3& q, const Vec3& qdot, const Vec3& qddot, double lambda0) const;
  double semichord;
  Mat3 Ma;   ///< apparent mass per unit density [m^2, m^3, m^4 by entry]
  Mat3 Cnc;  ///< non-circulatory terms proportional to U q'
  Mat3 Knc;  ///< non-circulatory terms proportional to U^2 q
  Vec3 es;   ///< projection of the Kutta loading 2 rho U Q / sin(phi) per 2 pi rho U b Q
  Vec3 ef;   ///< projection of the flat-plate loading 2 rho U lambda0 (1 - cos phi) / sin(phi) per 2 pi rho U b lambda0
  Vec3 ew;   ///< three-quarter-chord downwash per unit rate: w0 + w1/2 = ew^T q' + U eg^T q
  Vec3 eg;   ///< the same per unit U q
};

/// Downwash coefficients of the flap shape (REFERENCES section 5.3) in x = b cos(phi), phi = 0 at the trailing
/// edge: the shape (x - x_h) on the flap is sum f_n cos(n phi) and its slope (a unit step on the flap)
/// sum g_n cos(n phi), n = 0..num_terms-1; theta_h = acos(c).
void FlapShapeCoefficients(double semichord, double c, int num_terms, Eigen::VectorXd* f, Eigen::VectorXd* g);

}  // namespace flexmbd
