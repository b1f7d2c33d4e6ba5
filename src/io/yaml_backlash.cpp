#include <algorithm>
#include <cmath>

#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/urdf_limit.hpp"
#include "flexmbd/io/yaml_sections.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {
namespace io {
namespace {
const std::vector<std::string> kBacklashKeys = {"lower", "lower_deg", "upper",  "upper_deg",
                                                "radius_lower", "radius_upper", "stop", "retract"};
const std::vector<std::string> kStopKeys = {"type", "law", "stiffness", "exponent", "restitution", "steps_per_contact"};
const std::vector<std::string> kRetractKeys = {"joint", "above", "below"};

// A drive that ends on a stop (a table to the stop's position) touches it: only its time function's rounding
// separates the two, typed to the same value, so a drive counts as passing a stop beyond this fraction of
// max(1, |stop|).
constexpr double kTouchTolerance = 1.0e-9;

// `stop:` the contact model shared by the block's stops (rigid when absent).
void ReadContact(const Field& field, StopSpec* stop) {
  CheckKeys(field, kStopKeys);
  if (field.Child("type").present()) {
    stop->kind = ReadEnum<StopSpec::Kind>(field.Child("type"), "stop type",
                                          {{"rigid", StopSpec::Kind::kRigid}, {"elastic", StopSpec::Kind::kElastic}});
  }
  if (stop->kind == StopSpec::Kind::kRigid) {
    for (const char* key : {"law", "stiffness", "exponent", "restitution", "steps_per_contact"}) {
      if (field.Child(key).present()) field.Child(key).Fail("applies only to elastic stops; expected type: elastic");
    }
    return;
  }
  if (field.Child("law").present()) {
    stop->law = ReadEnum<StopSpec::Law>(field.Child("law"), "contact law",
                                        {{"linear", StopSpec::Law::kLinear}, {"hertz", StopSpec::Law::kHertz}});
  }
  const Quantity stiffness{"a contact stiffness", Bound::kPositive,
                           stop->law == StopSpec::Law::kLinear ? "N/m" : "N/m^n"};
  RequireKey(field, "stiffness", Expected(stiffness));
  stop->stiffness = ReadNumber(field.Child("stiffness"), stiffness);
  if (field.Child("exponent").present()) {
    if (stop->law != StopSpec::Law::kHertz) field.Child("exponent").Fail("applies only to law: hertz");
    stop->exponent = ReadNumber(field.Child("exponent"), Quantity{"a Hertz exponent", Bound::kAtLeastOne, ""});
  }
  OverlayNumber(field, "restitution", Quantity{"a coefficient of restitution", Bound::kPositiveFraction, ""},
                &stop->restitution);
  OverlayInteger(field, "steps_per_contact", Quantity{"a number of steps", Bound::kAtLeastOne, ""},
                 &stop->steps_per_contact);
}

// `retract:` the rule of a conditional stop.
void ReadRetraction(const Field& field, const VariableUnits& units, StopSpec::Retraction* retraction) {
  CheckKeys(field, kRetractKeys);
  const std::string speed_unit = units.position + "/s of the named joint";
  for (const char* key : {"joint", "above", "below"}) {
    RequireKey(field, key, "the retraction rule {joint, above, below}");
  }
  retraction->joint = ReadString(field.Child("joint"), "a joint name");
  retraction->retract_above = ReadNumber(field.Child("above"), Quantity{"a speed", Bound::kPositive, speed_unit});
  retraction->engage_below = ReadNumber(field.Child("below"), Quantity{"a speed", Bound::kNonNegative, speed_unit});
  if (!(retraction->engage_below < retraction->retract_above)) {
    field.Child("below").Fail(FormatNumber(retraction->engage_below) + " is not below 'above' (" +
                              FormatNumber(retraction->retract_above) + "); expected below < above");
  }
}

// Why the URDF <limit> gives `variable` of `joint` no stops, or "" where it does: it bounds variable 0, in the unit of
// the URDF's type (LeaveOutLimitOfAnotherUnit).
std::string WhyNoLimit(const JointSpec& joint, int variable, const VariableUnits& units) {
  const std::string joint_name = "joint '" + joint.name + "'";
  if (joint.limit_of_another_unit) {
    return "the URDF <limit> of " + joint_name + " is not in " + units.position + ", the unit of " +
           units.measure.description;
  }
  if (!joint.has_limits) return joint_name + " has no URDF <limit>";
  if (variable != 0) {
    return "the URDF <limit> of " + joint_name + " bounds variable 0, not " + units.measure.description;
  }
  return "";
}

// One backlash block: its lower and/or upper stop.
std::vector<StopSpec> ReadBlock(const Field& block, const JointSpec& joint, int variable, const VariableUnits& units,
                                const std::string& suffix, std::vector<std::string>* warnings) {
  CheckKeys(block, kBacklashKeys);
  const Quantity position{"a stop position", Bound::kAny, units.position};
  double lower = joint.limit_lower, upper = joint.limit_upper;
  const std::optional<UnitField> given_lower = OverlayMeasure(block, "lower", position, units.measure, &lower);
  const std::optional<UnitField> given_upper = OverlayMeasure(block, "upper", position, units.measure, &upper);
  if (given_lower) WarnStopOutsideUrdfLimit(*given_lower, lower, joint, variable, warnings);
  if (given_upper) WarnStopOutsideUrdfLimit(*given_upper, upper, joint, variable, warnings);
  const bool has_lower = given_lower.has_value(), has_upper = given_upper.has_value();
  const bool from_urdf = !has_lower && !has_upper;
  const std::string no_limit = WhyNoLimit(joint, variable, units);
  if (from_urdf && !no_limit.empty()) {
    block.Fail("gives no stop position and " + no_limit + "; expected lower and/or upper (or lower_deg, upper_deg)");
  }
  if ((from_urdf || (has_lower && has_upper)) && !(lower < upper)) {
    block.Fail("lower " + FormatNumber(lower) + " is not below upper " + FormatNumber(upper) + " [" + units.position +
               "]; expected lower < upper");
  }
  StopSpec contact;
  const Field stop_field = block.Child("stop");
  if (stop_field.present()) ReadContact(stop_field, &contact);
  const Field retract = block.Child("retract");
  if (retract.present()) ReadRetraction(retract, units, &contact.retraction);

  std::vector<StopSpec> stops;
  auto add = [&](StopSpec::Side side, double limit, const std::string& side_name) {
    StopSpec stop = contact;
    stop.side = side;
    stop.limit = limit;
    stop.name = side_name + suffix;
    const std::string radius_key = "radius_" + side_name;
    if (block.Child(radius_key).present()) {
      if (!units.measure.angular) {
        block.Child(radius_key).Fail("applies only to rotations; " + units.measure.description +
                                     " is a translation, whose gap is its travel; expected no " + radius_key);
      }
      stop.radius = ReadNumber(block.Child(radius_key), Quantity{"a contact radius", Bound::kPositive, "m"});
    }
    stops.push_back(stop);
  };
  if (has_lower || from_urdf) add(StopSpec::Side::kLower, lower, "lower");
  if (has_upper || from_urdf) add(StopSpec::Side::kUpper, upper, "upper");
  for (const char* side : {"lower", "upper"}) {
    const Field radius = block.Child(std::string("radius_") + side);
    const bool used =
        std::any_of(stops.begin(), stops.end(), [side](const StopSpec& s) { return s.name.rfind(side, 0) == 0; });
    if (radius.present() && !used) radius.Fail(std::string("there is no ") + side + " stop in this block");
  }
  return stops;
}
}  // namespace

void CheckDriveWithinRigidStops(const Field& drive, const VariableEffectsSpec& effects, double t_end,
                                const std::string& unit) {
  if (effects.drives.empty()) return;
  const ValueRange range = RangeOver(effects.drives.front(), 0.0, t_end);
  for (const StopSpec& stop : effects.stops) {
    // An elastic stop gives way (the drive presses into it); a retracting one may be out of the way by then.
    if (stop.kind != StopSpec::Kind::kRigid || !stop.retraction.joint.empty()) continue;
    const bool upper = stop.side == StopSpec::Side::kUpper;
    const double reached = upper ? range.greatest : range.least;
    const double beyond = upper ? reached - stop.limit : stop.limit - reached;
    if (beyond <= kTouchTolerance * std::max(1.0, std::abs(stop.limit))) continue;
    drive.Fail("the drive reaches " + FormatNumber(reached) + " [" + unit + "] at t = " +
               FormatNumber(upper ? range.t_greatest : range.t_least) + " s, beyond the rigid " + stop.name +
               " stop at " + FormatNumber(stop.limit) + " [" + unit + "] (solver.t_end " + FormatNumber(t_end) +
               " s): a prescribed motion cannot pass a rigid stop; expected a drive that stays within its rigid "
               "stops up to solver.t_end, an elastic stop (the drive then presses into it) or no stop there");
  }
}

std::vector<StopSpec> ReadBacklash(const Field& backlash, const JointSpec& joint, int variable,
                                   const VariableUnits& units, std::vector<std::string>* warnings) {
  if (!backlash.node().IsSequence()) return ReadBlock(backlash, joint, variable, units, "", warnings);
  std::vector<StopSpec> stops;
  const std::vector<Field> blocks = ListEntries(backlash, "a backlash block or a list of them");
  // An empty list would give the joint no stops while the key says it has some.
  if (blocks.empty()) {
    backlash.Fail("[] gives no stops; expected a backlash block or a list of them (no key: no stops)");
  }
  for (size_t k = 0; k < blocks.size(); ++k) {
    const std::vector<StopSpec> block =
        ReadBlock(blocks[k], joint, variable, units, k == 0 ? "" : "." + std::to_string(k), warnings);
    stops.insert(stops.end(), block.begin(), block.end());
  }
  return stops;
}

}  // namespace io
}  // namespace flexmbd
