#include "flexmbd/effects/contact_law.hpp"

#include <cmath>

namespace flexmbd {
namespace {
// Approaches closer than this fraction of their size are one point for the discrete gradient: below it the
// difference quotient loses more digits to cancellation than the midpoint rule's O(da^2) error costs.
constexpr double kCoincidentFraction = 1.0e-7;
// Bisection to the last few units in the last place of alpha_e.
constexpr int kBisections = 200;
}  // namespace

double HuntCrossleyDampingNumber(double e) {
  if (e >= 1.0) return 0.0;
  // f(alpha) = ln(1 + alpha) - ln(1 - alpha e) - alpha (1 + e) is negative near 0 (-(1 - e^2) alpha^2 / 2)
  // and tends to +infinity as alpha e -> 1, with one root in between.
  auto f = [e](double alpha) { return std::log1p(alpha) - std::log1p(-alpha * e) - alpha * (1.0 + e); };
  double low = 0.0, high = 1.0 / e;
  for (int k = 0; k < kBisections && high - low > 1e-15 * high; ++k) {
    const double mid = 0.5 * (low + high);
    (f(mid) < 0.0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

ContactLaw::ContactLaw(const StopSpec& stop)
    : stiffness_(stop.stiffness),
      exponent_(stop.law == StopSpec::Law::kLinear ? 1.0 : stop.exponent),
      damping_number_(HuntCrossleyDampingNumber(stop.restitution)) {}

double ContactLaw::Potential(double a) const {
  return a > 0 ? stiffness_ * std::pow(a, exponent_ + 1.0) / (exponent_ + 1.0) : 0.0;
}

double ContactLaw::Force(double a) const { return a > 0 ? stiffness_ * std::pow(a, exponent_) : 0.0; }

double ContactLaw::Stiffness(double a) const {
  // Out of contact the force is zero and so is its slope, for the linear law too: a slope there stiffened a static
  // tangent (where the approaches always coincide) against a residual without it. Touching (a = 0), the linear law
  // takes its contact side's slope: a joint pressed onto its stop.
  if (a < 0 || (a == 0 && !linear())) return 0.0;
  return exponent_ * stiffness_ * std::pow(a, exponent_ - 1.0);
}

double ContactLaw::ApproachAt(double force) const { return std::pow(force / stiffness_, 1.0 / exponent_); }

double ContactLaw::DiscreteForce(double a_i, double a_f, double* d_da_f) const {
  const double da = a_f - a_i;
  if (std::abs(da) <= kCoincidentFraction * std::max(std::abs(a_i), std::abs(a_f))) {
    const double mid = 0.5 * (a_i + a_f);
    *d_da_f = 0.5 * Stiffness(mid);
    return Force(mid);
  }
  const double gradient = (Potential(a_f) - Potential(a_i)) / da;
  *d_da_f = (Force(a_f) - gradient) / da;
  return gradient;
}

}  // namespace flexmbd
