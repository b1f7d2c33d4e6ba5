// `aero:` typical sections carrying unsteady thin-airfoil loads (docs/config.md, "aero").

#include "flexmbd/aero/typical_section_aero.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
const std::vector<std::string> kAeroKeys = {"sections"};
const std::vector<std::string> kSectionKeys = {"plunge", "pitch", "flap", "semichord", "a", "c",
                                               "span", "velocity", "density", "inflow_states"};

std::string ReadJointName(const Field& field, const UrdfModel& model, const std::string& what) {
  const std::string name = ReadString(field, "the name of the " + what + " joint (a URDF joint)");
  std::vector<std::string> names;
  for (const JointSpec& joint : model.spec.joints) {
    if (joint.name == name) return name;
    names.push_back(joint.name);
  }
  field.Fail(NotFoundMessage("joint", "joints", name, model.name, names));
}

// A position along the chord in semichords from mid-chord, strictly inside the chord.
double ReadChordPosition(const Field& field, const std::string& what) {
  const double value = ReadNumber(field, Quantity{what, Bound::kAny, ""});
  if (!(value > -1.0 && value < 1.0)) {
    field.Fail(field.Text() + " is off the chord; expected " + what + " with -1 < value < 1 (semichords aft of mid-chord)");
  }
  return value;
}

AeroSectionSpec ReadSection(const Field& entry, const std::string& name, const UrdfModel& model) {
  CheckKeys(entry, kSectionKeys);
  AeroSectionSpec section;
  section.name = name;
  for (const char* key : {"plunge", "pitch", "flap", "semichord", "a", "c", "velocity"}) {
    RequireKey(entry, key, "the section's " + std::string(key) + " (docs/config.md, \"aero\")");
  }
  section.plunge = ReadJointName(entry.Child("plunge"), model, "plunge (prismatic)");
  section.pitch = ReadJointName(entry.Child("pitch"), model, "pitch (revolute, at the elastic axis)");
  section.flap = ReadJointName(entry.Child("flap"), model, "flap (revolute, at the hinge)");
  section.semichord = ReadNumber(entry.Child("semichord"), Quantity{"a semichord", Bound::kPositive, "m"});
  section.a = ReadChordPosition(entry.Child("a"), "the elastic axis a");
  section.c = ReadChordPosition(entry.Child("c"), "the flap hinge c");
  section.velocity = ReadNumber(entry.Child("velocity"), Quantity{"a free-stream speed", Bound::kNonNegative, "m/s"});
  OverlayNumber(entry, "span", Quantity{"a span", Bound::kPositive, "m"}, &section.span);
  OverlayNumber(entry, "density", Quantity{"an air density", Bound::kPositive, "kg/m^3"}, &section.density);
  OverlayInteger(entry, "inflow_states", Quantity{"a number of inflow states", Bound::kNonNegative, ""},
                 &section.inflow_states);
  if (section.inflow_states > kMaxInflowStates) {
    entry.Child("inflow_states")
        .Fail(entry.Child("inflow_states").Text() + " is too many; expected 0 <= inflow_states <= " +
              std::to_string(kMaxInflowStates) + " (8 reproduce Theodorsen's function within 1% up to k = 1)");
  }
  return section;
}
}  // namespace

void ReadAero(const Field& aero, const UrdfModel& model, std::vector<AeroSectionSpec>* sections) {
  if (!aero.present()) return;
  CheckKeys(aero, kAeroKeys);
  const Field map = aero.Child("sections");
  for (const std::string& name : MapKeys(map, "a map from section names to typical sections")) {
    sections->push_back(ReadSection(map.Child(name), name, model));
  }
}

void CheckAirspeedSweep(const Field& root, const ModelSpec& spec) {
  if (spec.solver.eigen.sweep_airspeed.empty() || !spec.aero_sections.empty()) return;
  root.Child("solver").Child("eigen").Child("sweep").Child("airspeed").Fail(
      "sweeps the free-stream speed of the aero sections, but there are none; expected aero.sections (docs/config.md, "
      "\"aero\") or a sweep of velocity_scale");
}

}  // namespace io
}  // namespace flexmbd
