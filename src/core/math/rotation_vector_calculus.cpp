#include "flexmbd/math/rotation_vector_calculus.hpp"

#include <array>
#include <cmath>

namespace flexmbd {
namespace {

// Highest n of f_n needed: the second derivative of f_3 takes f_7.
constexpr int kHighest = 7;
using Ratios = std::array<double, kHighest + 1>;

// Below s = 4 (2 rad) the f_n are summed as series (see SeriesRatios): for n >= 1 the terms fall by at least
// s / ((2k + n + 1)(2k + n + 2)) < 1 each, so there is no cancellation. The sum stops once s^k / (2k)!, which
// bounds the next term relative to f_n ~ 1/n!, is below 1e-17: 4 terms at s = 1e-4, 12 at s = 4.
// Above it f_0 and f_1 come from cos and sin and the others from f_{n+2} = (1/n! - f_n) / s, which divides
// each error by about s / ((n + 1)(n + 2)): at most ~100 eps for f_7 at s = 4.
constexpr double kSeriesLimit = 4.0;
constexpr double kSeriesTruncation = 1.0e-17;
constexpr int kMaxTerms = 14;

// 1 / m! for m = 0 .. 2 kMaxTerms + kHighest.
struct InverseFactorials {
  std::array<double, 2 * kMaxTerms + kHighest + 1> value;
  InverseFactorials() {
    value[0] = 1.0;
    for (size_t m = 1; m < value.size(); ++m) value[m] = value[m - 1] / static_cast<double>(m);
  }
};

// f_0 .. f_highest: the top two summed as series, the others by the downward recursion
// f_n = 1/n! - s f_{n+2}, which multiplies an error by s < 4 per step down: at most 64 eps of f_highest ~ 1/7!
// reaches f_1 ~ 1, against the eps of its own rounding.
Ratios SeriesRatios(double s, int highest) {
  static const InverseFactorials inverse;
  Ratios f{};
  double power = 1.0;  // (-s)^k
  for (int k = 0; k < kMaxTerms; ++k) {
    f[highest - 1] += power * inverse.value[2 * k + highest - 1];
    f[highest] += power * inverse.value[2 * k + highest];
    if (std::abs(power) * inverse.value[2 * k] < kSeriesTruncation) break;
    power *= -s;
  }
  for (int n = highest - 2; n >= 0; --n) f[n] = inverse.value[n] - s * f[n + 2];
  return f;
}

Ratios ClosedRatios(double s, int highest) {
  Ratios f{};
  const double t = std::sqrt(s);
  f[0] = std::cos(t);
  f[1] = std::sin(t) / t;
  double factorial = 1.0;  // n!
  for (int n = 0; n + 2 <= highest; ++n) {
    if (n > 0) factorial *= n;
    f[n + 2] = (1.0 / factorial - f[n]) / s;
  }
  return f;
}

// Skew(u) Skew(v) + Skew(v) Skew(u) = u v^T + v u^T - 2 (u . v) I, without the two products.
Mat3 SkewProductSum(const Vec3& u, const Vec3& v) {
  return u * v.transpose() + v * u.transpose() - 2.0 * u.dot(v) * Mat3::Identity();
}

}  // namespace

RotationVectorCalculus::RotationVectorCalculus(const Vec3& psi, Level level) : psi_(psi) {
  const double s = psi.squaredNorm();
  // The maps take f_1..f_3; first derivatives f_5 (through f_3'), second derivatives f_7 (through f_3'').
  const int highest = level == Level::kMaps ? 3 : level == Level::kFirst ? 5 : kHighest;
  const Ratios f = s < kSeriesLimit ? SeriesRatios(s, highest) : ClosedRatios(s, highest);
  K_ = Skew(psi);
  K2_ = psi * psi.transpose() - s * Mat3::Identity();
  a_ = f[2];
  b_ = f[3];
  exp_ = Mat3::Identity() + f[1] * K_ + f[2] * K2_;
  tangent_ = Mat3::Identity() - a_ * K_ + b_ * K2_;
  if (level == Level::kMaps) return;
  // d f_n / ds and d2 f_n / ds2 from the identity f_n' = (n f_{n+2} - f_{n+1}) / 2.
  auto d1 = [&](int n) { return 0.5 * (n * f[n + 2] - f[n + 1]); };
  auto d2 = [&](int n) { return 0.5 * (n * d1(n + 2) - d1(n + 1)); };
  a_s_ = d1(2);
  b_s_ = d1(3);
  // c = u / v with u = (f_3 - 2 f_4) / 2, v = f_2.
  const double u = 0.5 * (f[3] - 2.0 * f[4]);
  c_ = u / f[2];
  inverse_tangent_ = Mat3::Identity() + 0.5 * K_ + c_ * K2_;
  if (level == Level::kFirst) return;
  a_ss_ = d2(2);
  b_ss_ = d2(3);
  const double u_s = 0.5 * (d1(3) - 2.0 * d1(4));
  c_s_ = (u_s * f[2] - u * d1(2)) / (f[2] * f[2]);
}

Mat3 RotationVectorCalculus::SecantDerivative(const Vec3& d) const {
  // f_1' = (f_3 - f_2) / 2 = (b - a) / 2 and f_2' = a_s, each times d(s) = 2 psi.d.
  const double ds = 2.0 * psi_.dot(d);
  return ds * (0.5 * (b_ - a_) * Mat3::Identity() + a_s_ * K_) + a_ * Skew(d);
}

Mat3 RotationVectorCalculus::TangentDerivative(const Vec3& d) const {
  const double pd = psi_.dot(d);
  return -a_ * Skew(d) + b_ * SkewProductSum(psi_, d) + 2.0 * pd * (-a_s_ * K_ + b_s_ * K2_);
}

Mat3 RotationVectorCalculus::TangentDerivativeApplied(const Vec3& w) const { return AppliedDerivative(w, 1.0); }

Mat3 RotationVectorCalculus::TransposedTangentDerivativeApplied(const Vec3& w) const {
  return AppliedDerivative(w, -1.0);
}

Mat3 RotationVectorCalculus::AppliedDerivative(const Vec3& w, double sign) const {
  // With K' = sign K, T(sign psi) w = w - a K' w + b K'^2 w; along d: -a d' x w + b (d' x K'w + K' (d' x w)) +
  // 2 (psi . d) (-a' K'w + b' K'^2 w) with d' = sign d, and d x u = -Skew(u) d.
  const Vec3 Kw = sign * (K_ * w);
  const Vec3 v = -a_s_ * Kw + b_s_ * (K2_ * w);
  return sign * (a_ * Skew(w) - b_ * (Skew(Kw) + sign * (K_ * Skew(w)))) + 2.0 * v * psi_.transpose();
}

Mat3 RotationVectorCalculus::TangentSecondDerivative(const Vec3& d1, const Vec3& d2) const {
  const double p1 = psi_.dot(d1), p2 = psi_.dot(d2);
  return b_ * SkewProductSum(d1, d2) + 2.0 * p2 * (-a_s_ * Skew(d1) + b_s_ * SkewProductSum(d1, psi_)) +
         2.0 * p1 * (-a_s_ * Skew(d2) + b_s_ * SkewProductSum(d2, psi_)) +
         2.0 * d1.dot(d2) * (-a_s_ * K_ + b_s_ * K2_) +
         4.0 * p1 * p2 * (-a_ss_ * K_ + b_ss_ * K2_);
}

Mat3 RotationVectorCalculus::TangentSecondDerivativeForm(const Vec3& m, const Vec3& v) const {
  // Term by term of TangentSecondDerivative: m.(D1 D2 v) = d1^T Skew(m) Skew(v) d2, m.(D1 v) = d1.(v x m),
  // m.((D1 K + K D1) v) = d1.((K v) x m + v x (K^T m)).
  const Mat3 X = Skew(m) * Skew(v);
  const Vec3 Kv = K_ * v;
  const Vec3 gamma = -a_s_ * v.cross(m) + b_s_ * (Kv.cross(m) + v.cross(K_.transpose() * m));
  const double mKv = m.dot(Kv), mK2v = m.dot(K_ * Kv);
  const double c0 = -a_s_ * mKv + b_s_ * mK2v, c1 = -a_ss_ * mKv + b_ss_ * mK2v;
  return b_ * (X + X.transpose()) + 2.0 * (gamma * psi_.transpose() + psi_ * gamma.transpose()) +
         2.0 * c0 * Mat3::Identity() + 4.0 * c1 * psi_ * psi_.transpose();
}

Mat3 RotationVectorCalculus::InverseTangentDerivative(const Vec3& d) const {
  return 0.5 * Skew(d) + c_ * SkewProductSum(psi_, d) + 2.0 * c_s_ * psi_.dot(d) * K2_;
}

}  // namespace flexmbd
