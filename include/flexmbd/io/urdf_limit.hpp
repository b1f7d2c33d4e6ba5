#pragma once
/// @file
/// YAML values checked against a joint's URDF <limit> (the range of variable 0 of a revolute or prismatic joint,
/// docs/config.md "URDF mapping"): an initial position, a stop or a drive's path outside it gives a warning.

#include <string>
#include <vector>

#include "flexmbd/io/yaml_fields.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// Leaves out the URDF <limit> of `joint` (has_limits false, limit_of_another_unit true) where the YAML `type` gave
/// its variable 0 the other unit than the URDF's type did (radians against metres): the limit's values would be read
/// in the wrong unit, in the warnings below and as default stops. Adds to `warnings` a line naming the type field,
/// the joint, both types and both units. `urdf_type` is the joint's type before the YAML's.
void LeaveOutLimitOfAnotherUnit(const Field& type, JointType urdf_type, JointSpec* joint,
                                std::vector<std::string>* warnings);

/// Adds to `warnings` a line naming `position_field` (initial.position or position_deg) if `position` [rad or m], the
/// initial position of `variable` of `joint`, lies outside the joint's URDF <limit>. Only for variable 0 of a joint
/// with a <limit>, no stops and no drive from the YAML: the model checks a start against the stops, and a drive's
/// start is its path's (WarnDriveLeavingUrdfLimit). A warning, not an error: nothing in the model holds a joint to
/// its <limit> but stops, so a start outside it is a state the model can be in (a rod hanging below its droop stop's
/// angle with the stop left out).
void WarnInitialOutsideUrdfLimit(const UnitField& position_field, double position, const JointSpec& joint,
                                 int variable, std::vector<std::string>* warnings);

/// Adds to `warnings` a line naming `stop` (backlash lower or upper, or their _deg forms) if `position` [rad or m],
/// a stop of variable 0 of `joint`, lies outside the joint's URDF <limit>: a wider or narrower stop may be
/// deliberate, but degrees typed under a radian key look the same.
void WarnStopOutsideUrdfLimit(const UnitField& stop, double position, const JointSpec& joint, int variable,
                              std::vector<std::string>* warnings);

/// Adds to `warnings` a line naming `drive` if its law, over [0, t_end] [s] (its start included), takes variable 0 of
/// `joint` outside the joint's URDF <limit>: nothing in the model holds a joint to its <limit> but stops, so the drive
/// moves it there, as a free motion could go there too. `unit` is the variable's.
void WarnDriveLeavingUrdfLimit(const Field& drive, double t_end, const JointSpec& joint, int variable,
                               const std::string& unit, std::vector<std::string>* warnings);

}  // namespace io
}  // namespace flexmbd
