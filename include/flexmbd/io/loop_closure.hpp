#pragma once
/// @file
/// The initial motion of the joints that close kinematic loops (YAML `closures:`, docs/config.md), once the
/// tree has placed the bodies.

#include <string>

#include <Eigen/Core>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// For each joint with `closes_loop`: the initial variables that put its child frame (on the child as placed)
/// where its parent frame (on the parent as placed) carries it, and the initial rates that carry the child's
/// initial motion relative to the parent frame.
/// @throws ConfigError naming `source` and the first closure left open: no variables of the joint close its
/// loop (the frames lie apart across what the joint allows), or the initial motion opens it.
/// @pre the bodies and beams are placed (PlaceBodies).
void CloseLoops(const std::string& source, ModelSpec* spec);

/// What the closing joints leave open on the bodies as placed, six numbers each in the order of spec.joints:
/// the rotation vector [rad] and offset [m] of the child's joint frame from where the joint's best-fitting
/// variables put it, in the parent's joint frame. Zero when every loop closes.
Eigen::VectorXd LoopPoseGaps(const ModelSpec& spec);

/// As LoopPoseGaps for the initial motion: the child joint frame's angular [rad/s] and linear [m/s] velocity
/// relative to the parent's joint frame across what the joint's best-fitting rates allow.
Eigen::VectorXd LoopMotionGaps(const ModelSpec& spec);

}  // namespace io
}  // namespace flexmbd
