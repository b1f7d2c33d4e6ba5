#pragma once
/// @file
/// Initial poses and velocities of the bodies by forward kinematics through the joint tree
/// (docs/config.md, "Initial state").

#include <vector>

#include "flexmbd/io/urdf_reader.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// Pose and velocity of a frame F in the world W.
struct FrameMotion {
  Mat3 R_WF = Mat3::Identity();
  Vec3 p_WF = Vec3::Zero();     ///< [m]
  Vec3 v_WFo_W = Vec3::Zero();  ///< velocity of the F origin [m/s]
  Vec3 w_WF_W = Vec3::Zero();   ///< angular velocity [rad/s]
};

/// Motion of a frame F fixed on frame P at pose (R_PF, p_PF): R_WF = R_WP R_PF, p_WF = p_WP + R_WP p_PF,
/// w_WF = w_WP, v_WFo = v_WPo + w_WP x (p_WF - p_WP).
FrameMotion CarryRigidly(const FrameMotion& P, const Mat3& R_PF, const Vec3& p_PF);

/// Motion of the child frame C of `joint` given the motion of its parent frame P, with the joint's
/// relative motion (RelativePose, RelativeVelocity) at its initial_position and initial_velocity, and (a
/// spherical joint's) initial_rotation and initial_angular_velocity:
///   Jp = CarryRigidly(P, R_PJ, p_PJ); R_WJc = R_WJp R_JpJc; p_WJc = p_WJp + R_WJp p_JpJc;
///   w_WJc = w_WJp + R_WJp w_JpJc; v_WJc = v_WJp + w_WJp x (R_WJp p_JpJc) + R_WJp v_JpJc;
///   C = CarryRigidly(Jc, R_CJ^T, -R_CJ^T p_CJ).
/// @pre initial_position and initial_velocity have NumJointVariables(type) entries.
FrameMotion ChildMotion(const FrameMotion& P, const JointSpec& joint);

/// Sets p_WB, R_WB, v_WBo_W and w_WB_W of every body from the world outwards: a body that is the child of
/// a joint by ChildMotion, a body in `free_bodies` by CarryRigidly from its mount.
/// Joints that close loops (`closes_loop`) are left out: CloseLoops attaches them afterwards.
/// @pre every body is placed by exactly one joint (not closing a loop) or mount, and those joints form a tree.
void PlaceBodies(const std::vector<BodyMount>& free_bodies, ModelSpec* spec);

}  // namespace io
}  // namespace flexmbd
