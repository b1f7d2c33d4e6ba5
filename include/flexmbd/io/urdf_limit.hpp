#pragma once
/// @file
/// YAML values checked against a joint's URDF <limit> (the range of variable 0 of a revolute or prismatic joint,
/// docs/config.md "URDF mapping"): an initial position outside it is an error, a stop or a drive's path outside it a
/// warning.

#include <string>
#include <vector>

#include "flexmbd/io/yaml_fields.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// Fails at `source` (initial.position, initial.position_deg or drive) if `position` [rad or m], the initial position
/// of `variable` of `joint`, lies outside the joint's URDF <limit>. Checks only variable 0 of a joint with a <limit>
/// and no stops from the YAML: stops, where given, bound the motion instead, and the model checks the initial
/// position against them.
void CheckInitialWithinUrdfLimit(const UnitField& source, double position, const JointSpec& joint, int variable);

/// Adds to `warnings` a line naming `stop` (backlash lower or upper, or their _deg forms) if `position` [rad or m],
/// a stop of variable 0 of `joint`, lies outside the joint's URDF <limit>: a wider or narrower stop may be
/// deliberate, but degrees typed under a radian key look the same.
void WarnStopOutsideUrdfLimit(const UnitField& stop, double position, const JointSpec& joint, int variable,
                              std::vector<std::string>* warnings);

/// Adds to `warnings` a line naming `drive` if its law, over [0, t_end] [s], takes variable 0 of `joint` outside the
/// joint's URDF <limit> (its start is checked as an initial position): nothing in the model holds a joint to its
/// <limit> but stops, so the drive moves it there, as a free motion could go there too. `unit` is the variable's.
void WarnDriveLeavingUrdfLimit(const Field& drive, double t_end, const JointSpec& joint, int variable,
                               const std::string& unit, std::vector<std::string>* warnings);

}  // namespace io
}  // namespace flexmbd
