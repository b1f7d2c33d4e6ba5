#pragma once
// Closed forms the verification tests compare with.

#include <cmath>
#include <vector>

namespace flexmbd {
namespace test {

// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean (exact to round-off):
// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
inline double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return M_PI / (2.0 * a);
}

// A slider-crank whose slide passes through the crank's axis (crank r, rod l): the slider's travel from its place
// at crank angle 0, x = r cos(theta) + sqrt(l^2 - r^2 sin^2(theta)) - (r + l), and its rate dx/dtheta.
inline double SliderTravel(double r, double l, double theta) {
  const double s = r * std::sin(theta);
  return r * std::cos(theta) + std::sqrt(l * l - s * s) - (r + l);
}
inline double SliderTravelRate(double r, double l, double theta) {
  const double s = r * std::sin(theta);
  return -s - s * r * std::cos(theta) / std::sqrt(l * l - s * s);
}

// Bending moment at station s of a uniform bar of length l and weight per length w, hinged at s = 0 and turning
// rigidly under gravity at angle theta from the horizontal: the transverse load w cos(theta) (1 - 3 sigma / (2 l))
// (gravity less the inertia of the angular acceleration 3 g cos(theta) / (2 l)) times the arm sigma - s,
// integrated from s to l. Positive when it bends the bar as its weight bends a cantilever.
inline double FallingBarMoment(double w, double l, double s, double theta) {
  const double shear_arm = 0.5 * (l - s) * (l - s);
  const double inertia_arm = 1.5 / l * ((l * l * l - s * s * s) / 3.0 - s * (l * l - s * s) / 2.0);
  return w * std::cos(theta) * (shear_arm - inertia_arm);
}

// Bending moment at station s of the same bar held at its root at angle theta: a cantilever under its weight.
inline double CantileverMoment(double w, double l, double s, double theta) {
  return 0.5 * w * std::cos(theta) * (l - s) * (l - s);
}

// Time a uniform bar of length l hinged at one end takes to fall rigidly from rest at theta0 above the horizontal
// to the horizontal: theta'' = -a cos(theta), a = 3 g / (2 l), so theta'^2 = 2 a (sin(theta0) - sin(theta)) and
// t = int_0^sqrt(sin theta0) 2 dv / sqrt(2 a (1 - (sin theta0 - v^2)^2)) with sin(theta) = sin(theta0) - v^2,
// a smooth integrand: Simpson's rule on 1000 intervals is exact to round-off.
inline double RigidFallTime(double g, double l, double theta0) {
  const double a = 1.5 * g / l, s0 = std::sin(theta0), top = std::sqrt(s0);
  auto f = [&](double v) {
    const double s = s0 - v * v;
    return 2.0 / std::sqrt(2.0 * a * (1.0 - s * s));
  };
  constexpr int kIntervals = 1000;
  const double h = top / kIntervals;
  double sum = f(0.0) + f(top);
  for (int k = 1; k < kIntervals; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * f(k * h);
  return sum * h / 3.0;
}

// A uniform Euler-Bernoulli beam (length l, mass per length m, bending stiffness ei, structural damping mu as
// in docs/config.md, transverse load per length w), pinned at s = 0 and free at l, released at t = 0 from rest in
// its cantilever shape under the same load (linear theory, small rotations). Modal solution with the first
// `modes` flexible modes of the pinned-free beam, phi = sin(b s) + (sin(b l) / sinh(b l)) sinh(b s) with
// tan(b l) = tanh(b l), omega = b^2 sqrt(ei / m), damping ratio zeta = mu omega / 2: each modal coordinate moves
// from the cantilever shape's projection q0 to the load's static share qs = f / (M omega^2) as a damped free
// vibration. Overdamped modes (omega >= 2 / mu) are left out: they relax with time constants of about mu. The
// rigid rotation has no curvature.
class ReleasedCantilever {
 public:
  ReleasedCantilever(double w, double m, double ei, double mu, double l, int modes) {
    constexpr int kIntervals = 2000;  // Simpson's rule for the modal integrals (smooth integrands)
    const double h = l / kIntervals;
    auto cantilever = [&](double s) { return w * s * s * (6 * l * l - 4 * l * s + s * s) / (24 * ei); };
    for (int k = 0; k < modes; ++k) {
      // the root of tan(b) = tanh(b) near (k + 1.25) pi, by bisection
      double lo = (k + 1.25) * M_PI - 0.3, hi = (k + 1.25) * M_PI + 0.3;
      auto f = [](double b) { return std::tan(b) - std::tanh(b); };
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) * f(lo) > 0 ? lo : hi) = mid;
      }
      Mode mode;
      mode.b = 0.5 * (lo + hi) / l;
      mode.ratio = std::sin(mode.b * l) / std::sinh(mode.b * l);
      double mass = 0, load = 0, shape = 0;  // Simpson sums; their common factor h / 3 cancels below
      for (int i = 0; i <= kIntervals; ++i) {
        const double s = i * h, weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
        const double phi = std::sin(mode.b * s) + mode.ratio * std::sinh(mode.b * s);
        mass += weight * m * phi * phi;
        load += weight * w * phi;
        shape += weight * m * cantilever(s) * phi;
      }
      mode.omega = mode.b * mode.b * std::sqrt(ei / m);
      mode.zeta = 0.5 * mu * mode.omega;
      if (mode.zeta >= 1.0) break;
      mode.q_static = load / (mass * mode.omega * mode.omega);
      mode.q0 = shape / mass;
      modes_.push_back(mode);
    }
  }

  // Bending curvature at s, time t; positive as w bends a cantilever [1/m].
  double Curvature(double s, double t) const {
    double curvature = 0;
    for (const Mode& mode : modes_) {
      const double phi_ss = mode.b * mode.b * (-std::sin(mode.b * s) + mode.ratio * std::sinh(mode.b * s));
      const double damped = mode.omega * std::sqrt(1.0 - mode.zeta * mode.zeta);
      const double free = std::exp(-mode.zeta * mode.omega * t) *
                          (std::cos(damped * t) + mode.zeta * mode.omega / damped * std::sin(damped * t));
      curvature += phi_ss * (mode.q_static + (mode.q0 - mode.q_static) * free);
    }
    return curvature;
  }

 private:
  struct Mode {
    double b, ratio, omega, zeta, q_static, q0;
  };
  std::vector<Mode> modes_;
};

// Contact of a mass m arriving at speed v on an elastic stop F = k a^n (approach a; lossless), pressed on by a
// constant acceleration g (gravity) along the approach. Without g, m a'' = -k a^n gives the deepest approach
// a_max = (p m v^2 / (2 k))^(1/p), p = n + 1, and the duration 2 (a_max / v) I, I = int_0^1 (1 - u^p)^(-1/2) du =
// B(1/p, 1/2) / p (Johnson, Contact Mechanics, sec. 11.4); for n = 1.5, 3.2181 (m^2 / (k^2 v))^(1/5). With g the
// half duration is dJ/dE of the action J = int sqrt(2 (E + g a) - 2 k a^p / (p m)) da, E = v^2 / 2, so its first
// order in g is d^2 J / dE dg = d/dE int a da / sqrt(2 E - 2 k a^p / (p m)) = (2/p - 1/2) a_max^2 I_1 / (v E), I_1 =
// B(2/p, 1/2) / p: the duration grows by g 4 (2/p - 1/2) I_1 a_max^2 / v^3 (the ball of hertz_ball_drop.yaml:
// 1.04e-6 s, 6.4e-4 of 1.616 ms; the rest is O(g^2), 4e-7 of the duration).
inline double ElasticContactDuration(double m, double k, double n, double v, double g = 0.0) {
  const double p = n + 1.0;
  const double a_max = std::pow(p * m * v * v / (2.0 * k), 1.0 / p);
  auto beta = [](double x, double y) { return std::tgamma(x) * std::tgamma(y) / std::tgamma(x + y); };
  const double integral = beta(1.0 / p, 0.5) / p, moment = beta(2.0 / p, 0.5) / p;
  return 2.0 * a_max / v * integral + g * 4.0 * (2.0 / p - 0.5) * moment * a_max * a_max / (v * v * v);
}

}  // namespace test
}  // namespace flexmbd
