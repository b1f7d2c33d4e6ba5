#pragma once
/// @file
/// Kinematic assembly of the initial configuration: the tree joints the YAML leaves free are moved so that
/// every loop closes (docs/theory.md, "Assembly of the initial configuration").

#include <vector>

#include "flexmbd/io/urdf_reader.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// Moves the initial positions of the tree's variables not set in the YAML (position_set; spherical joints by
/// initial_rotation) by the least change, Gauss-Newton step by step, until LoopPoseGaps vanish; then their
/// rates (velocity_set; initial_angular_velocity) by the least change that zeroes LoopMotionGaps. Places the
/// bodies at the result. Leaves a loop that cannot close as open as least squares leave it, for CloseLoops
/// to refuse.
/// @pre the bodies are placed (PlaceBodies) with `free_bodies`.
void AssembleLoops(const std::vector<BodyMount>& free_bodies, ModelSpec* spec);

}  // namespace io
}  // namespace flexmbd
