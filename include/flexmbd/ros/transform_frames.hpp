#pragma once
/// @file
/// The tf tree the node sends, shaped like the URDF (as robot_state_publisher gives it): each link is a child
/// of its URDF parent link; links that move (bodies, beams) go on /tf, massless links fixed by a fixed joint
/// on /tf_static; each beam node has a frame under its beam link. Names and placements are built once per
/// model, not per step.

#include <string>
#include <vector>

#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace ros {

/// Where a frame F is: at pose (R_NF, p_NF_N) relative to node `node`, or, for node = -1, relative to the
/// world frame (a frame fixed to the ground).
struct FramePlacement {
  int node = -1;
  Mat3 R_NF = Mat3::Identity();
  Vec3 p_NF_N = Vec3::Zero();  ///< [m]
};

/// A frame that moves with the model: sent on /tf as the transform from `parent` to it.
struct TransformFrame {
  std::string name;                 ///< tf child frame id
  std::string parent;               ///< tf parent frame id
  FramePlacement placement;         ///< of the frame itself
  FramePlacement parent_placement;  ///< of its parent frame
};

/// A frame fixed to its parent link (a URDF link without <inertial> below a fixed joint): sent once on
/// /tf_static as the joint's origin.
struct StaticFrame {
  std::string name;
  std::string parent;
  Mat3 R_PF = Mat3::Identity();
  Vec3 p_PF = Vec3::Zero();  ///< [m]
};

struct FrameTree {
  /// The URDF's root link when it is the ground (no body, no beam), so tf joins the frames of a URDF whose
  /// root is e.g. "base_link"; otherwise (a free-floating root) "world", the root link's parent.
  std::string world_frame;
  std::vector<TransformFrame> moving;  ///< in URDF tree order; a beam link is followed by its node frames
  std::vector<StaticFrame> fixed;      ///< in URDF tree order
};

/// Name of the frame of node `k` (0 at the root) of the beam on URDF link `beam`: "<beam>/node_<k>".
std::string BeamNodeFrameName(const std::string& beam, size_t k);

/// The frames of `model`, whose tree is that of the URDF `urdf_xml`. A body's link frame is at its node
/// (x + R p_NBo_N, with the node's axes); a beam link's frame is its root node's (node frames have the
/// section axes, x along the centre line, and at rest those of the link); the frame of beam node k is
/// placed by that node. The tree is walked without recursion.
/// @pre `model` was loaded from `urdf_xml`.
FrameTree UrdfFrameTree(const std::string& urdf_xml, const Model& model);

}  // namespace ros
}  // namespace flexmbd
