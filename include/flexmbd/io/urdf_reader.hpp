#pragma once
/// @file
/// URDF -> bodies and joints of a ModelSpec (docs/config.md, "URDF mapping"). Initial poses are placed
/// later, after the YAML overlay has set the joints' initial motion (initial_placement.hpp).

#include <map>
#include <set>
#include <string>
#include <vector>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// Where a body without a JointSpec (a free-floating root, or the child of a URDF floating joint) starts:
/// at pose X_PB on `parent` (empty for the world), moving rigidly with it.
struct BodyMount {
  std::string body;
  std::string parent;            ///< parent body; empty for the world
  Mat3 R_PB = Mat3::Identity();  ///< orientation of the body frame in the parent frame
  Vec3 p_PB = Vec3::Zero();      ///< body origin in the parent frame [m]
};

/// Where a link's frame sits: on a body or beam (empty name: the ground), at pose X_body_link.
struct LinkFrame {
  std::string body;
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
};

/// What a URDF contributes to a model, and what the YAML overlay needs to know about it.
struct UrdfModel {
  std::string name;  ///< the URDF's file name, for messages
  ModelSpec spec;    ///< bodies (mass properties, poses not yet placed) and joints (frames, axes, URDF dampers)
  std::vector<BodyMount> free_bodies;  ///< bodies that no JointSpec places
  /// URDF joints that have no JointSpec, with the reason (a fixed joint to a link without <inertial>, which
  /// becomes a frame of its parent body, or a floating joint).
  std::map<std::string, std::string> frame_joints;
  std::map<std::string, LinkFrame> link_frames;  ///< every link of the URDF
};

/// Reads a URDF. The links named in `beam_links` become beams (BeamSpec with only name and frame set; their
/// <inertial>, if any, is not used: the beam's section gives its mass). Throws ConfigError naming
/// `urdf_name` if urdfdom cannot parse it, if its links are not one tree or a name would break the CSV
/// (CheckUrdfTree), if nothing can move (no body and no beam), if a link that moves has no <inertial>, if a mass
/// is not positive or an inertia not positive semi-definite, or if a damping is negative; and naming the field
/// beams.<link> of `beam_links_file` (the YAML that names them) if a beam link is not in it. The tree is walked
/// without recursion.
UrdfModel ReadUrdf(const std::string& urdf_xml, const std::string& urdf_name,
                   const std::set<std::string>& beam_links = {}, const std::string& beam_links_file = "");

/// Sizes a joint's initial_position, initial_velocity and effects to NumJointVariables(type), keeping the
/// entries of the variables it already had and zero-filling new ones.
void ResizeJointVariables(JointSpec* joint);

}  // namespace io
}  // namespace flexmbd
