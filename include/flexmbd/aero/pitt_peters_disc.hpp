#pragma once
/// @file
/// The momentum rows of Pitt and Peters' three-state dynamic inflow (docs/theory.md, (A14)): the loads
/// (T, M_c / R, M_s / R) that hold the disc's induced flow nu = nu_0 + (r/R)(nu_c cos psi + nu_s sin psi) steady,
/// the inverse of Peters and HaQuang's gain matrix L written without the wake skew angle, smooth through hover.

#include <Eigen/Core>

namespace flexmbd {

/// The rows and their Jacobian by (nu_0, nu_c, nu_s).
struct DiscMomentum {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();   ///< (T, M_c / R, M_s / R) [N]
  Eigen::Matrix3d slope = Eigen::Matrix3d::Zero();   ///< d value / d nu [N s/m]
};

/// @param climb V_c, the stream's speed down through the disc [m/s]; @param in_plane the stream's in-plane
/// velocity in the disc frame (e_c, e_s) [m/s]; @param nu (nu_0, nu_c, nu_s) [m/s]; @param rho_area rho pi R^2
/// [kg/m]. With no flow through the disc at all (V_T = 0) the rows and their slopes vanish, as (A13)'s do.
DiscMomentum PittPetersMomentum(double climb, const Eigen::Vector2d& in_plane, const Eigen::Vector3d& nu,
                                double rho_area);

}  // namespace flexmbd
