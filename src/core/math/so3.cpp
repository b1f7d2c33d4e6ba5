#include "flexmbd/math/so3.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "flexmbd/math/so3_generic.hpp"

namespace flexmbd {
namespace {
// Below this angle sin(x)/x uses its Taylor series; the truncated term x^6/5040 is < 1e-27 there.
constexpr double kSincSeriesLimit = 1.0e-4;
}  // namespace

Mat3 Skew(const Vec3& a) { return so3::SkewOf<double>(a); }

Vec3 Axial(const Mat3& A) {
  return 0.5 * Vec3(A(2, 1) - A(1, 2), A(0, 2) - A(2, 0), A(1, 0) - A(0, 1));
}

double Sinc(double x) { return std::abs(x) < kSincSeriesLimit ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

Mat3 Exp(const Vec3& theta) { return so3::ExpOf<double>(theta); }

Vec3 Log(const Mat3& R) {
  const Eigen::AngleAxisd angle_axis(R);
  return angle_axis.angle() * angle_axis.axis();
}

Mat3 AxisAngle(const Vec3& unit_axis, double angle) { return Exp(angle * unit_axis); }

Mat3 RightJacobian(const Vec3& theta) { return so3::RightJacobianOf<double>(theta); }

Mat3 SecantOperator(const Vec3& theta) {
  double sin_ratio, cos_ratio;
  so3::SinRatios(theta.squaredNorm(), &sin_ratio, &cos_ratio);
  return sin_ratio * Mat3::Identity() + cos_ratio * Skew(theta);
}

}  // namespace flexmbd
