#pragma once
// Peters and HaQuang's (1988) gain matrix L of Pitt and Peters' three-state inflow, as published (with the wake skew
// angle, in the stream's own frame): the steady induced flow a disc's loads hold (docs/theory.md, (A14)). Written
// apart from the core's inverse (src/core/aero/pitt_peters_disc.cpp) to check it.

#include <Eigen/Core>
#include <cmath>

namespace flexmbd {
namespace test {

// (nu_0, nu_c, nu_s) from the rows (T, M_c / R, M_s / R) of a disc whose stream has the climb speed `climb` and the
// in-plane velocity w (disc frame), with rho pi R^2 = rho_area and the uniform inflow nu0. In the stream's frame
// (psi = 0 downstream: e_p along w, e_q = axis x e_p) with C_T = T, the nose-up pitch moment C_M = -M_p / R and
// the roll moment C_L = -M_q / R (all over rho A), chi = atan(|w| / lambda), lambda = climb + nu0,
// V_T = |(w, lambda)|, V_m = (|w|^2 + lambda (lambda + nu_0)) / V_T:
//   L = [1/(2 V_T), 0, a/V_m; 0, -b/V_m, 0; a/V_T, 0, -d/V_m],  (nu_0, nu_q, nu_p) = L (C_T, C_L, C_M),
//   a = (15 pi / 64) tan(chi / 2), b = 4 / (1 + cos chi), d = 4 cos chi / (1 + cos chi).
inline Eigen::Vector3d PublishedPittPetersInflow(double climb, const Eigen::Vector2d& w, double nu0,
                                                 const Eigen::Vector3d& rows, double rho_area) {
  const double lambda = climb + nu0, chi = std::atan2(w.norm(), lambda);
  const double VT = std::hypot(w.norm(), lambda), Vm = (w.squaredNorm() + lambda * (lambda + nu0)) / VT;
  const double a = 15.0 * M_PI / 64.0 * std::tan(chi / 2.0), b = 4.0 / (1.0 + std::cos(chi)),
               d = 4.0 * std::cos(chi) / (1.0 + std::cos(chi));
  const Eigen::Vector2d p = w.norm() > 0.0 ? Eigen::Vector2d(w / w.norm()) : Eigen::Vector2d::UnitX();
  const Eigen::Vector2d q(-p.y(), p.x());
  const Eigen::Vector2d moment = rows.tail<2>();
  const double CT = rows[0] / rho_area, CM = -p.dot(moment) / rho_area, CL = -q.dot(moment) / rho_area;
  const double nu_0 = CT / (2.0 * VT) + a / Vm * CM, nu_q = -b / Vm * CL, nu_p = a / VT * CT - d / Vm * CM;
  const Eigen::Vector2d harmonic = nu_p * p + nu_q * q;
  return Eigen::Vector3d(nu_0, harmonic.x(), harmonic.y());
}

}  // namespace test
}  // namespace flexmbd
