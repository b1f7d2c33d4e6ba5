#pragma once
/// @file
/// Checks and defaults for joint axes shared by the URDF reader and the YAML overlay.

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// True if both vectors are non-zero and the sine of the angle between them is below 1e-6.
bool AreParallel(const Vec3& a, const Vec3& b);

/// The default second axis of a joint (universal joint, in-plane x of a planar joint) in the joint frame:
/// x, or y if `axis` is along x.
Vec3 DefaultSecondAxis(const Vec3& axis);

}  // namespace io
}  // namespace flexmbd
