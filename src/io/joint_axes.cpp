#include "flexmbd/io/joint_axes.hpp"

#include <Eigen/Geometry>

namespace flexmbd {
namespace io {
namespace {
// Sine of the angle below which two axes count as parallel: well above rounding of unit vectors typed with
// a few digits, well below any intended angle.
constexpr double kParallelSine = 1.0e-6;
}  // namespace

bool AreParallel(const Vec3& a, const Vec3& b) {
  if (a.norm() == 0.0 || b.norm() == 0.0) return false;
  return a.normalized().cross(b.normalized()).norm() < kParallelSine;
}

Vec3 DefaultSecondAxis(const Vec3& axis) { return AreParallel(axis, Vec3::UnitX()) ? Vec3::UnitY() : Vec3::UnitX(); }

}  // namespace io
}  // namespace flexmbd
