#pragma once
/// @file
/// urdfdom's vectors and rotations as Eigen types.

#include <urdf_model/pose.h>

#include "flexmbd/math/so3.hpp"

namespace flexmbd {
namespace io {

Vec3 ToVec3(const urdf::Vector3& v);

/// The rotation matrix of a URDF quaternion, normalised (URDF values are printed with few digits).
Mat3 ToMat3(const urdf::Rotation& r);

}  // namespace io
}  // namespace flexmbd
