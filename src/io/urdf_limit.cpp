#include "flexmbd/io/urdf_limit.hpp"

#include <algorithm>
#include <cmath>

#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {
namespace io {
namespace {
// A position on the <limit> within this fraction of max(1, |bound|) counts as on it: values are typed by hand or
// are a drive's values, which only the time function's rounding separates from the bound it was written to reach.
constexpr double kLimitTolerance = 1.0e-9;

const double kRadiansPerDegree = M_PI / 180.0;

bool LimitApplies(const JointSpec& joint, int variable) { return variable == 0 && joint.has_limits; }

bool WithinLimit(double position, const JointSpec& joint) {
  const double lower = joint.limit_lower - kLimitTolerance * std::max(1.0, std::abs(joint.limit_lower));
  const double upper = joint.limit_upper + kLimitTolerance * std::max(1.0, std::abs(joint.limit_upper));
  return position >= lower && position <= upper;
}

// "the URDF <limit> [-1.5, 1.5] [rad] of joint 'hinge'"
std::string LimitText(const JointSpec& joint, const std::string& unit) {
  return "the URDF <limit> [" + FormatNumber(joint.limit_lower) + ", " + FormatNumber(joint.limit_upper) + "] [" +
         unit + "] of joint '" + joint.name + "'";
}

// The SI unit of the variable: the limit's, whatever unit the field is written in.
std::string SiUnit(const UnitField& field) { return field.unit == "deg" ? "rad" : field.unit; }

// "30 [rad]", or "30 [deg] (0.5235987755982988 rad)" for a field in degrees.
std::string WrittenValue(const UnitField& field, double position) {
  const std::string written = field.field.Text() + " [" + field.unit + "]";
  return field.to_si == 1.0 ? written : written + " (" + FormatNumber(position) + " " + SiUnit(field) + ")";
}

// "; if 30 is in degrees, write position_deg: 30" when the value, read as degrees, lies within the <limit>.
std::string DegreesHint(const UnitField& field, double position, const JointSpec& joint) {
  if (field.unit != "rad" || !WithinLimit(position * kRadiansPerDegree, joint)) return "";
  const std::string& path = field.field.path();
  const std::string key = path.substr(path.find_last_of('.') + 1);
  return "; if " + field.field.Text() + " is in degrees, write " + key + "_deg: " + field.field.Text();
}
}  // namespace

void LeaveOutLimitOfAnotherUnit(const Field& type, JointType urdf_type, JointSpec* joint,
                                std::vector<std::string>* warnings) {
  if (!joint->has_limits || NumJointVariables(joint->type) == 0) return;
  // A URDF <limit> is read on revolute and prismatic joints only (urdf_reader.cpp).
  const std::string limit_unit = urdf_type == JointType::kRevolute ? "rad" : "m";
  const std::string unit = UnitsOf(*joint, 0).position;
  if (unit == limit_unit) return;
  warnings->push_back(type.Message(
      "the URDF's " + std::string(JointTypeName(urdf_type)) + " joint '" + joint->name + "' made " +
      JointTypeName(joint->type) + ": its <limit> [" + FormatNumber(joint->limit_lower) + ", " +
      FormatNumber(joint->limit_upper) + "] is in " + limit_unit + ", variable 0 of a " + JointTypeName(joint->type) +
      " joint in " + unit + "; the <limit> is left out (no stops from it, no values checked against it)"));
  joint->has_limits = false;
  joint->limit_of_another_unit = true;
}

void WarnInitialOutsideUrdfLimit(const UnitField& position_field, double position, const JointSpec& joint,
                                 int variable, std::vector<std::string>* warnings) {
  const VariableEffectsSpec& effects = joint.effects[variable];
  if (!LimitApplies(joint, variable) || !effects.stops.empty() || !effects.drives.empty()) return;
  if (WithinLimit(position, joint)) return;
  warnings->push_back(position_field.field.Message(
      WrittenValue(position_field, position) + " is outside " + LimitText(joint, SiUnit(position_field)) +
      ": without stops (backlash) nothing holds the joint to its <limit>" +
      DegreesHint(position_field, position, joint)));
}

void WarnStopOutsideUrdfLimit(const UnitField& stop, double position, const JointSpec& joint, int variable,
                              std::vector<std::string>* warnings) {
  if (!LimitApplies(joint, variable) || WithinLimit(position, joint)) return;
  warnings->push_back(stop.field.Message(WrittenValue(stop, position) + " is outside " +
                                         LimitText(joint, SiUnit(stop)) +
                                         ": this stop, not the <limit>, bounds the motion" +
                                         DegreesHint(stop, position, joint)));
}

void WarnDriveLeavingUrdfLimit(const Field& drive, double t_end, const JointSpec& joint, int variable,
                               const std::string& unit, std::vector<std::string>* warnings) {
  if (!LimitApplies(joint, variable)) return;
  const ValueRange range = RangeOver(joint.effects[variable].drives.front(), 0.0, t_end);
  const bool below = !WithinLimit(range.least, joint);
  if (!below && WithinLimit(range.greatest, joint)) return;
  const double reached = below ? range.least : range.greatest, t = below ? range.t_least : range.t_greatest;
  warnings->push_back(drive.Message("the drive reaches " + FormatNumber(reached) + " [" + unit + "] at t = " +
                                    FormatNumber(t) + " s, outside " + LimitText(joint, unit) +
                                    " (solver.t_end " + FormatNumber(t_end) +
                                    " s): the drive, not the <limit>, sets the motion"));
}

}  // namespace io
}  // namespace flexmbd
