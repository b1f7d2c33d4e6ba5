// Pitt and Peters' three-state inflow: the momentum rows and their slopes (docs/theory.md, (A14)).

#include "flexmbd/aero/pitt_peters_disc.hpp"

#include <cmath>

namespace flexmbd {
namespace {
// 15 pi / 64: the skewed wake's coupling of nu_0 and the harmonic along the stream (Pitt and Peters 1981).
const double kSkew = 15.0 * M_PI / 64.0;

// A value and its derivative by nu_0, the one state the coefficients of (A14) depend on.
struct Dual {
  double v, d;
};
Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.d + b.d}; }
Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
Dual operator/(Dual a, Dual b) { return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)}; }
Dual Constant(double v) { return {v, 0.0}; }
Dual Sqrt(Dual a) {
  const double r = std::sqrt(a.v);
  return {r, 0.5 * a.d / r};
}
}  // namespace

DiscMomentum PittPetersMomentum(double climb, const Eigen::Vector2d& in_plane, const Eigen::Vector3d& nu,
                                double rho_area) {
  DiscMomentum out;
  const double w2 = in_plane.squaredNorm();
  const Dual nu0{nu[0], 1.0}, lambda{climb + nu[0], 1.0}, W2 = Constant(w2);
  const Dual VT = Sqrt(W2 + lambda * lambda);
  if (!(VT.v > 0.0)) return out;
  const Eigen::Vector2d g = nu.tail<2>(), &w = in_plane;
  const double wg = w.dot(g);
  // (A14): s = V_T + lambda, D = 2 lambda s + kappa^2 |w|^2, V_m = (|w|^2 + lambda (lambda + nu_0)) / V_T.
  const Dual s = VT + lambda, D = Constant(2.0) * lambda * s + Constant(kSkew * kSkew) * W2;
  const Dual Vm = (W2 + lambda * (lambda + nu0)) / VT;
  // T = rho A V_T s (4 lambda nu_0 + kappa w.g) / D
  const Dual thrust = Constant(rho_area) * VT * s * (Constant(4.0) * lambda * nu0 + Constant(kSkew * wg)) / D;
  out.value[0] = thrust.v;
  out.slope(0, 0) = thrust.d;
  out.slope.block<1, 2>(0, 1) = (rho_area * VT.v * s.v * kSkew / D.v) * w.transpose();
  // M / R = rho A V_m [-kappa s nu_0 / D w + s / (4 V_T) g + (2 - kappa^2) s / (4 D V_T) (w.g) w]
  const Dual along = Constant(-kSkew) * s * nu0 / D, own = s / (Constant(4.0) * VT);
  const Dual skew = Constant(2.0 - kSkew * kSkew) * s / (Constant(4.0) * D * VT);
  const Dual scale = Constant(rho_area) * Vm;
  const Dual on_w = scale * (along + skew * Constant(wg)), on_g = scale * own;
  out.value.tail<2>() = on_w.v * w + on_g.v * g;
  out.slope.block<2, 1>(1, 0) = on_w.d * w + on_g.d * g;
  out.slope.block<2, 2>(1, 1) = on_g.v * Eigen::Matrix2d::Identity() + (scale.v * skew.v) * w * w.transpose();
  return out;
}

}  // namespace flexmbd
