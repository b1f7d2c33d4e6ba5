#include "flexmbd/io/urdf_pose.hpp"

#include <Eigen/Geometry>

namespace flexmbd {
namespace io {

Vec3 ToVec3(const urdf::Vector3& v) { return Vec3(v.x, v.y, v.z); }

Mat3 ToMat3(const urdf::Rotation& r) { return Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix(); }

}  // namespace io
}  // namespace flexmbd
