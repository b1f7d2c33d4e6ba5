#include <algorithm>
#include <cmath>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/joint_axes.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/urdf_limit.hpp"
#include "flexmbd/io/yaml_sections.hpp"
#include "flexmbd/joints/joint_kinematics.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {
namespace io {
namespace {
// A given initial value of a driven variable must match the drive at t = 0 to this relative tolerance:
// both are typed by hand, and the same degree conversion is applied to each, so only rounding of the
// time function's arithmetic separates equal inputs.
constexpr double kDriveStartTolerance = 1.0e-9;

// Newton resolves a variable to about 100 units in the last place of its magnitude (RoundOffFloor): 2.2e-8 at
// 1e6 rad or m, under the tightest joint error floor the step control follows (1e-7 rad, at error_tol 1e-7).
// Further out the step's own motion drowns in round-off (B1 of the antenna at 1.6e9 rad took 63,000 steps for
// its first 0.03 s).
constexpr double kLargestInitialPosition = 1.0e6;

const std::vector<std::string> kJointKeys = {"type",    "axis",  "axis2",    "pitch",   "spring",  "damper",
                                             "initial", "drive", "backlash", "friction", "variables"};
const std::vector<std::string> kVariableKeys = {"spring", "damper", "initial", "drive", "backlash", "friction"};

// Names of the relative-motion variables, in order (joint_kinematics.hpp).
std::vector<std::string> VariableNames(JointType type) {
  switch (type) {
    case JointType::kRevolute: return {"phi"};
    case JointType::kPrismatic: return {"s"};
    case JointType::kCylindrical: return {"phi", "s"};
    case JointType::kScrew: return {"phi"};
    case JointType::kPlanar: return {"phi", "x", "y"};
    case JointType::kUniversal: return {"phi1", "phi2"};
    case JointType::kSpherical:
    case JointType::kFixed: return {};
  }
  return {};
}

std::string JointLabel(const JointSpec& joint) {
  return std::string(JointTypeName(joint.type)) + " joint '" + joint.name + "'";
}

}  // namespace

VariableUnits UnitsOf(const JointSpec& joint, int variable) {
  const JointKinematics kinematics = MakeJointKinematics(joint);
  const bool angular = std::any_of(kinematics.rotations.begin(), kinematics.rotations.end(),
                                   [variable](const RotationFactor& factor) { return factor.variable == variable; });
  const std::string description =
      "variable " + std::to_string(variable) + " (" + VariableNames(joint.type)[variable] + ") of " + JointLabel(joint);
  if (angular) return {{true, description}, "rad", "N m/rad", "N m s/rad"};
  return {{false, description}, "m", "N/m", "N s/m"};
}

namespace {

JointSpec* FindJoint(const Field& field, const std::string& name, UrdfModel* model) {
  std::vector<std::string> names;
  for (JointSpec& joint : model->spec.joints) {
    if (joint.name == name) return &joint;
    names.push_back(joint.name);
  }
  const auto frame = model->frame_joints.find(name);
  if (frame != model->frame_joints.end()) {
    field.Fail("joint '" + name + "' of " + model->name + " has nothing to configure: " + frame->second);
  }
  field.Fail(NotFoundMessage("joint", "joints", name, model->name, names));
}

void ReadJointType(const Field& field, JointSpec* joint) {
  const Field type = field.Child("type");
  if (!type.present()) return;
  std::vector<std::pair<std::string, JointType>> types;
  for (JointType t : {JointType::kRevolute, JointType::kPrismatic, JointType::kCylindrical, JointType::kScrew,
                      JointType::kPlanar, JointType::kSpherical, JointType::kUniversal, JointType::kFixed}) {
    types.emplace_back(JointTypeName(t), t);
  }
  joint->type = ReadEnum(type, "joint type", types);
}

// axis2 (universal, planar) and pitch (screw) apply to some types only; a screw needs its pitch.
void ReadTypeParameters(const Field& field, JointSpec* joint) {
  const Field axis2 = field.Child("axis2");
  if (axis2.present()) {
    if (joint->type != JointType::kUniversal && joint->type != JointType::kPlanar) {
      axis2.Fail("applies only to universal and planar joints; this is a " + JointLabel(*joint));
    }
    joint->axis2_J = ReadVec3(axis2, Quantity{"a second axis in the joint frame", Bound::kAny, ""});
  }
  const Field pitch = field.Child("pitch");
  const Quantity pitch_quantity{"a screw pitch", Bound::kAny, "m/rev"};
  if (joint->type == JointType::kScrew) {
    RequireKey(field, "pitch", Expected(pitch_quantity) + " for a screw joint");
    joint->pitch = ReadNumber(pitch, pitch_quantity);
  } else if (pitch.present()) {
    pitch.Fail("applies only to screw joints; this is a " + JointLabel(*joint));
  }
}

void CheckSecondAxis(const Field& field, const JointSpec& joint) {
  const Field axis2 = field.Child("axis2");
  if (axis2.present() && AreParallel(joint.axis_J, joint.axis2_J)) {
    axis2.Fail(axis2.Text() + " is parallel to the joint axis " + FormatVector(joint.axis_J) +
               "; expected a second axis not parallel to the first");
  }
}

// The URDF's <dynamics> act on variable 0 (urdf_reader.cpp); a type without variables (spherical, fixed) would drop
// them without a word, where the other types carry them or refuse them (ValidateFriction).
void CheckUrdfDynamicsKept(const Field& field, const JointSpec& joint) {
  if (NumJointVariables(joint.type) > 0 || joint.effects.empty()) return;
  const VariableEffectsSpec& urdf = joint.effects.front();
  if (urdf.dampers.empty() && urdf.frictions.empty()) return;
  const bool damping = !urdf.dampers.empty(), friction = !urdf.frictions.empty();
  const std::string what = damping && friction ? "<dynamics damping> and <dynamics friction>"
                           : damping           ? "<dynamics damping>"
                                               : "<dynamics friction>";
  field.Child("type").Fail("a " + JointLabel(joint) + " has no variable to carry the URDF's " + what +
                           "; expected no <dynamics> on a joint made " + JointTypeName(joint.type) +
                           " (or a type with a variable)");
}

void CheckKinematics(const Field& field, const JointSpec& joint) {
  try {
    MakeJointKinematics(joint);
  } catch (const ConfigError& error) {
    field.Fail(error.what());
  }
}

// The one field among `sources` that gives `key` (absent if none does).
Field Pick(const std::vector<Field>& sources, const std::string& key) {
  for (const Field& source : sources) {
    if (source.Child(key).present()) return source.Child(key);
  }
  return sources.front().Child(key);
}

SpringSpec ReadSpring(const Field& field, const VariableUnits& units) {
  CheckKeys(field, {"k", "rest", "rest_deg"});
  const Quantity stiffness{"a stiffness", Bound::kNonNegative, units.stiffness};
  RequireKey(field, "k", Expected(stiffness));
  SpringSpec spring;
  spring.stiffness = ReadNumber(field.Child("k"), stiffness);
  OverlayMeasure(field, "rest", Quantity{"a rest position", Bound::kAny, units.position}, units.measure, &spring.rest);
  return spring;
}

DamperSpec ReadDamper(const Field& field, const VariableUnits& units) {
  CheckKeys(field, {"c"});
  const Quantity coefficient{"a damping coefficient", Bound::kNonNegative, units.damping};
  RequireKey(field, "c", Expected(coefficient));
  return DamperSpec{ReadNumber(field.Child("c"), coefficient)};
}

// A given initial value of a driven variable must equal the drive's value (or rate) at t = 0.
void CheckOnDrive(const Field& initial, const std::string& what, double given, double start, const std::string& unit) {
  if (std::abs(given - start) > kDriveStartTolerance * std::max(1.0, std::abs(start))) {
    initial.Fail(what + " " + FormatNumber(given) + " [" + unit + "] differs from the drive's " + what + " " +
                 FormatNumber(start) + " [" + unit + "] at t = 0; expected a driven variable to start on its drive");
  }
}

void ReadInitial(const Field& initial, const Field& drive, const VariableUnits& units, int variable, JointSpec* joint) {
  CheckKeys(initial, {"position", "position_deg", "velocity", "velocity_deg", "static_hold"});
  OverlayBool(initial, "static_hold", &joint->effects[variable].static_hold);
  double& position = joint->initial_position[variable];
  double& velocity = joint->initial_velocity[variable];
  const std::string rate_unit = units.position + "/s";
  const Quantity position_quantity{"an initial position", Bound::kAny, units.position};
  const Quantity velocity_quantity{"an initial velocity", Bound::kAny, rate_unit};
  const bool position_given =
      OverlayMeasure(initial, "position", position_quantity, units.measure, &position).has_value();
  const bool velocity_given =
      OverlayMeasure(initial, "velocity", velocity_quantity, units.measure, &velocity).has_value();
  joint->position_set[variable] = position_given;
  joint->velocity_set[variable] = velocity_given;
  if (!drive.present()) return;
  // a driven variable starts on its drive: q(0) = f(0), qdot(0) = f'(0)
  const TimeFunctionSpec& f = joint->effects[variable].drives.front();
  if (position_given) CheckOnDrive(initial, "position", position, Evaluate(f, 0.0), units.position);
  if (velocity_given) CheckOnDrive(initial, "velocity", velocity, EvaluateRate(f, 0.0), rate_unit);
  position = Evaluate(f, 0.0);
  velocity = EvaluateRate(f, 0.0);
  joint->position_set[variable] = joint->velocity_set[variable] = true;
}

// The field that sets a variable's initial position: its drive, or initial.position or position_deg; none if the
// position is the URDF's zero.
std::optional<UnitField> InitialPositionSource(const Field& initial, const Field& drive, const VariableUnits& units) {
  if (drive.present()) return UnitField{drive, 1.0, units.position};
  return FindUnitField(initial, "position", units.position, units.measure);
}

void CheckResolvable(const Field& source, double position, const std::string& unit) {
  if (std::abs(position) <= kLargestInitialPosition) return;
  source.Fail("an initial position of " + FormatNumber(position) + " [" + unit + "] is beyond what the solver " +
              "resolves; expected an initial position within +-" + FormatNumber(kLargestInitialPosition) + " [" +
              unit + "]");
}

// A loop's closing joint starts where the tree puts its child (docs/config.md, "closures").
void CheckNotSetOnClosure(const std::vector<Field>& sources, const JointSpec& joint) {
  if (!joint.closes_loop) return;
  for (const char* key : {"initial", "drive"}) {
    const Field field = Pick(sources, key);
    if (field.present()) {
      field.Fail("the " + JointLabel(joint) + " closes a loop (closures." + joint.name +
                 "): its motion follows from the joints of the tree; expected the initial motion or a drive on "
                 "a joint of the URDF");
    }
  }
}

// What a variable's values are checked against besides their own fields: the end of the motion the run follows (a
// drive's path up to it) and where the warnings go.
struct RunBounds {
  double t_end;  ///< [s]
  std::vector<std::string>* warnings;
};

// Effects and initial motion of one variable, each key taken from whichever of `sources` gives it.
void ReadVariable(const std::vector<Field>& sources, int variable, JointSpec* joint, const RunBounds& run) {
  CheckNotSetOnClosure(sources, *joint);
  const VariableUnits units = UnitsOf(*joint, variable);
  VariableEffectsSpec& effects = joint->effects[variable];
  const Field spring = Pick(sources, "spring");
  if (spring.present()) effects.springs = {ReadSpring(spring, units)};
  const Field damper = Pick(sources, "damper");
  if (damper.present()) effects.dampers = {ReadDamper(damper, units)};
  const Field drive = Pick(sources, "drive");
  if (drive.present()) effects.drives = {ReadTimeFunction(drive, units.position, units.measure)};
  const Field backlash = Pick(sources, "backlash");
  if (backlash.present()) effects.stops = ReadBacklash(backlash, *joint, variable, units, run.warnings);
  CheckDriveWithinRigidStops(drive, effects, run.t_end, units.position);
  const Field friction = Pick(sources, "friction");
  if (friction.present()) effects.frictions = {ReadFriction(friction, units)};
  const Field initial = Pick(sources, "initial");
  ReadInitial(initial, drive, units, variable, joint);
  const std::optional<UnitField> source = InitialPositionSource(initial, drive, units);
  if (!source) return;
  const double position = joint->initial_position[variable];
  CheckResolvable(source->field, position, units.position);
  if (drive.present()) {
    WarnDriveLeavingUrdfLimit(drive, run.t_end, *joint, variable, units.position, run.warnings);
  } else {
    WarnInitialOutsideUrdfLimit(*source, position, *joint, variable, run.warnings);
  }
}

std::vector<Field> ReadVariableList(const Field& field, const JointSpec& joint) {
  const Field list = field.Child("variables");
  const std::vector<Field> entries =
      ListEntries(list, "a list of per-variable settings {spring, damper, initial, drive, backlash, friction}");
  const std::vector<std::string> names = VariableNames(joint.type);
  if (entries.size() > names.size()) {
    list.Fail("has " + std::to_string(entries.size()) + " entries; the " + JointLabel(joint) + " has " +
              std::to_string(names.size()) + " variable(s)" + (names.empty() ? "" : " (" + JoinNames(names) + ")"));
  }
  for (const Field& entry : entries) CheckKeys(entry, kVariableKeys);
  return entries;
}

// The shorthand keys configure variable 0, which must exist and not be configured twice.
void CheckShorthand(const Field& field, const JointSpec& joint, const std::vector<Field>& entries) {
  for (const std::string& key : kVariableKeys) {
    const Field shorthand = field.Child(key);
    if (!shorthand.present()) continue;
    if (NumJointVariables(joint.type) == 0)
      shorthand.Fail("the " + JointLabel(joint) + " has no relative-motion variables");
    if (!entries.empty() && entries.front().Child(key).present()) {
      entries.front().Child(key).Fail("variable 0 is also configured by " + shorthand.path() +
                                      "; expected one of the two forms");
    }
  }
}

void ReadVariables(const Field& field, JointSpec* joint, const RunBounds& run) {
  const std::vector<Field> entries = ReadVariableList(field, *joint);
  CheckShorthand(field, *joint, entries);
  for (int i = 0; i < NumJointVariables(joint->type); ++i) {
    std::vector<Field> sources;
    if (i == 0) sources.push_back(field);
    if (static_cast<size_t>(i) < entries.size()) sources.push_back(entries[i]);
    if (!sources.empty()) ReadVariable(sources, i, joint, run);
  }
}

void ReadJoint(const Field& field, JointSpec* joint, const RunBounds& run) {
  CheckKeys(field, kJointKeys);
  if (joint->closes_loop) {
    for (const char* key : {"type", "axis", "axis2", "pitch"}) {
      if (field.Child(key).present()) {
        field.Child(key).Fail("the " + JointLabel(*joint) + " is a closure: its geometry is given under closures." +
                              joint->name + "; expected only effects here");
      }
    }
  } else {
    const JointType urdf_type = joint->type;
    ReadJointGeometry(field, joint);
    LeaveOutLimitOfAnotherUnit(field.Child("type"), urdf_type, joint, run.warnings);
  }
  ReadVariables(field, joint, run);
}
}  // namespace

void ReadJointGeometry(const Field& field, JointSpec* joint) {
  ReadJointType(field, joint);
  OverlayVec3(field, "axis", Quantity{"a joint axis in the joint frame", Bound::kAny, ""}, &joint->axis_J);
  joint->axis2_J = DefaultSecondAxis(joint->axis_J);  // URDF has no second axis: only the YAML sets one
  ReadTypeParameters(field, joint);
  CheckSecondAxis(field, *joint);
  CheckKinematics(field, *joint);
  CheckUrdfDynamicsKept(field, *joint);
  ResizeJointVariables(joint);
}

void ReadJoints(const Field& joints, UrdfModel* model) {
  // a static or eigen-analysis takes the drives at t = 0 only
  const SolverSpec& solver = model->spec.solver;
  const double run_end = solver.analysis == SolverSpec::Analysis::kDynamic ? solver.t_end : 0.0;
  for (const std::string& name : MapKeys(joints, "a map from URDF joint names to joint settings")) {
    const Field field = joints.Child(name);
    ReadJoint(field, FindJoint(field, name, model), RunBounds{run_end, &model->spec.warnings});
  }
}

}  // namespace io
}  // namespace flexmbd
