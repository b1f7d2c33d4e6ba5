#include "flexmbd/math/so3.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "flexmbd/math/so3_generic.hpp"

namespace flexmbd {
namespace {
// Below this angle sin(x)/x uses its Taylor series; the truncated term x^6/5040 is < 1e-27 there.
constexpr double kSincSeriesLimit = 1.0e-4;
}  // namespace

IncrementMaps IncrementMapsOf(const Vec3& theta) {
  const double x2 = theta.squaredNorm();
  double sin_ratio, cos_ratio;
  so3::SinRatios(x2, &sin_ratio, &cos_ratio);
  const Mat3 K = Skew(theta);
  IncrementMaps maps;
  maps.exp = so3::ExpFromRatios<double>(K, sin_ratio, cos_ratio);
  maps.secant = so3::SecantFromRatios<double>(K, sin_ratio, cos_ratio);
  maps.right_jacobian = so3::RightJacobianFromRatios<double>(K, cos_ratio, so3::CubicRatio(x2));
  return maps;
}

double Sinc(double x) { return std::abs(x) < kSincSeriesLimit ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

Mat3 Exp(const Vec3& theta) { return so3::ExpOf<double>(theta); }

Vec3 Log(const Mat3& R) {
  // Below a quarter turn the skew part, sin(angle) times the axis, fixes the axis well and no quaternion is
  // needed (the beams' local rotations, the hot case); nearer a half turn it vanishes, and Eigen's quaternion
  // path, which takes the axis from the diagonal, is used.
  const double cos_angle = 0.5 * (R.trace() - 1.0);
  if (cos_angle > 0.0) {
    const Vec3 sin_axis = Axial(R);
    const double sin_angle = sin_axis.norm();
    const double ratio = sin_angle < kSincSeriesLimit ? 1.0 + sin_angle * sin_angle / 6.0
                                                      : std::atan2(sin_angle, cos_angle) / sin_angle;
    return ratio * sin_axis;
  }
  const Eigen::AngleAxisd angle_axis(R);
  return angle_axis.angle() * angle_axis.axis();
}

Mat3 AxisAngle(const Vec3& unit_axis, double angle) { return Exp(angle * unit_axis); }

Mat3 RightJacobian(const Vec3& theta) { return so3::RightJacobianOf<double>(theta); }

Mat3 SecantOperator(const Vec3& theta) {
  double sin_ratio, cos_ratio;
  so3::SinRatios(theta.squaredNorm(), &sin_ratio, &cos_ratio);
  return so3::SecantFromRatios<double>(Skew(theta), sin_ratio, cos_ratio);
}

}  // namespace flexmbd
