#pragma once
/// @file
/// The initial motion of the joints that close kinematic loops (YAML `closures:`, docs/config.md), once the
/// tree has placed the bodies.

#include <string>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// For each joint with `closes_loop`: the initial variables that put its child frame (on the child as placed)
/// where its parent frame (on the parent as placed) carries it, and the initial rates that carry the child's
/// initial motion relative to the parent frame.
/// @throws ConfigError naming `source` and the closure if no variables of the joint close the loop (the frames
/// lie apart across what the joint allows), or if the initial motion opens it.
/// @pre the bodies and beams are placed (PlaceBodies).
void CloseLoops(const std::string& source, ModelSpec* spec);

}  // namespace io
}  // namespace flexmbd
