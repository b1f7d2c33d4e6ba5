#include "flexmbd/math/so3.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace flexmbd {
namespace {
// Below this angle sin(x)/x uses its Taylor series; the truncated term x^6/5040 is < 1e-27 there.
constexpr double kSincSeriesLimit = 1.0e-4;
// Below this angle (x - sin x)/x^3 uses its series: the first omitted term, x^16/19!, is < 1e-16 relative
// there, while the closed form above it loses at most 6 eps / x^2 < 6e-15 to cancellation.
constexpr double kCubicSeriesLimit = 0.5;

// (1 - cos x) / x^2 written as sinc(x/2)^2 / 2: no cancellation at any angle.
double OneMinusCosOverSquare(double x) {
  const double s = Sinc(0.5 * x);
  return 0.5 * s * s;
}

// (x - sin x) / x^3 = sum_k (-1)^k x^(2k) / (2k + 3)!
double XMinusSinOverCube(double x) {
  if (std::abs(x) >= kCubicSeriesLimit) return (x - std::sin(x)) / (x * x * x);
  const double x2 = x * x;
  double term = 1.0 / 6.0, sum = 0.0;
  for (int k = 0; k < 8; ++k) {
    sum += term;
    term *= -x2 / ((2 * k + 4) * (2 * k + 5));
  }
  return sum;
}
}  // namespace

Mat3 Skew(const Vec3& a) {
  Mat3 S;
  S << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return S;
}

Vec3 Axial(const Mat3& A) {
  return 0.5 * Vec3(A(2, 1) - A(1, 2), A(0, 2) - A(2, 0), A(1, 0) - A(0, 1));
}

double Sinc(double x) { return std::abs(x) < kSincSeriesLimit ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

Mat3 Exp(const Vec3& theta) {
  const double angle = theta.norm();
  const Mat3 K = Skew(theta);
  return Mat3::Identity() + Sinc(angle) * K + OneMinusCosOverSquare(angle) * K * K;
}

Vec3 Log(const Mat3& R) {
  const Eigen::AngleAxisd angle_axis(R);
  return angle_axis.angle() * angle_axis.axis();
}

Mat3 AxisAngle(const Vec3& unit_axis, double angle) { return Exp(angle * unit_axis); }

Mat3 RightJacobian(const Vec3& theta) {
  const double angle = theta.norm();
  const Mat3 K = Skew(theta);
  return Mat3::Identity() - OneMinusCosOverSquare(angle) * K + XMinusSinOverCube(angle) * K * K;
}

Mat3 SecantOperator(const Vec3& theta) {
  const double angle = theta.norm();
  return Sinc(angle) * Mat3::Identity() + OneMinusCosOverSquare(angle) * Skew(theta);
}

}  // namespace flexmbd
