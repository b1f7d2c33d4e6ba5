#pragma once
/// @file
/// The frames the node sends on /tf: every rigid body's link frame and a frame per beam node. Their names
/// are built once per model, not per step.

#include <string>
#include <vector>

#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace ros {

/// A frame carried by a node of the model.
struct TransformFrame {
  std::string name;              ///< tf child frame id
  int node = -1;                 ///< the node that carries it
  Vec3 p_NF_N = Vec3::Zero();    ///< frame origin relative to the node, in the node frame [m]
};

/// Name of the frame of node `k` (0 at the root) of the beam on URDF link `beam`: "<beam>/node_<k>".
std::string BeamNodeFrameName(const std::string& beam, size_t k);

/// The bodies' link frames (named as the links, at node x + R p_NBo_N) in Model::bodies() order, then every
/// beam's node frames (at the node, with its section axes: x along the centre line) from root to tip.
std::vector<TransformFrame> TransformFrames(const Model& model);

}  // namespace ros
}  // namespace flexmbd
