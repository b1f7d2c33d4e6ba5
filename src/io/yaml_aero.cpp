// `aero:` typical sections and strips along beams carrying unsteady thin-airfoil loads, and the air they move in
// (docs/config.md, "aero").

#include <algorithm>
#include <cmath>
#include <utility>

#include "flexmbd/aero/typical_section_aero.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
const std::vector<std::string> kAeroKeys = {"sections", "strips", "rotors", "free_stream", "density", "gust"};
const std::vector<std::string> kRotorKeys = {"strips", "radius", "axis", "inflow", "center"};
const std::vector<std::string> kStripKeys = {"beam",        "semichord",     "a",   "chord_axis",
                                             "normal_axis", "inflow_states", "flap"};
const std::vector<std::string> kFlapKeys = {"beam", "c"};
const std::vector<std::string> kGustKeys = {"velocity", "scale"};
// Chord and normal axes count as perpendicular (to each other and to the beam axis) when their cosines are below
// this: axes written to six figures are.
constexpr double kPerpendicular = 1.0e-6;
const std::vector<std::string> kAeroSectionKeys = {"plunge", "pitch",    "flap",    "semichord", "a",
                                                   "c",      "span",     "velocity", "density",  "inflow_states"};

std::string ReadJointName(const Field& field, const UrdfModel& model, const std::string& what) {
  const std::string name = ReadString(field, "the name of the " + what + " joint (a URDF joint)");
  std::vector<std::string> names;
  for (const JointSpec& joint : model.spec.joints) {
    if (joint.name == name) return name;
    names.push_back(joint.name);
  }
  field.Fail(NotFoundMessage("joint", "joints", name, model.name, names));
}

void ReadInflowStates(const Field& entry, int* states) {
  OverlayInteger(entry, "inflow_states", Quantity{"a number of inflow states", Bound::kNonNegative, ""}, states);
  if (*states > kMaxInflowStates) {
    entry.Child("inflow_states")
        .Fail(entry.Child("inflow_states").Text() + " is too many; expected 0 <= inflow_states <= " +
              std::to_string(kMaxInflowStates) + " (8 reproduce Theodorsen's function within 1% up to k = 1)");
  }
}

// A position along the chord in semichords from mid-chord, strictly inside the chord.
double ReadChordPosition(const Field& field, const std::string& what) {
  const double value = ReadNumber(field, Quantity{what, Bound::kAny, ""});
  if (!(value > -1.0 && value < 1.0)) {
    field.Fail(field.Text() + " is off the chord; expected " + what +
               " with -1 < value < 1 (semichords aft of mid-chord)");
  }
  return value;
}

AeroSectionSpec ReadSection(const Field& entry, const std::string& name, const UrdfModel& model) {
  CheckKeys(entry, kAeroSectionKeys);
  AeroSectionSpec section;
  section.name = name;
  for (const char* key : {"plunge", "pitch", "flap", "semichord", "a", "c", "velocity"}) {
    RequireKey(entry, key, "the section's " + std::string(key) + " (docs/config.md, \"aero\")");
  }
  section.plunge = ReadJointName(entry.Child("plunge"), model, "plunge (prismatic)");
  section.pitch = ReadJointName(entry.Child("pitch"), model, "pitch (revolute, at the elastic axis)");
  section.flap = ReadJointName(entry.Child("flap"), model, "flap (revolute, at the hinge)");
  // One joint in two roles would move the section twice by one variable (and pitch and flap are both revolute,
  // so the joint types do not catch it).
  const std::pair<const char*, const std::string*> roles[] = {
      {"plunge", &section.plunge}, {"pitch", &section.pitch}, {"flap", &section.flap}};
  for (int k = 1; k < 3; ++k) {
    for (int j = 0; j < k; ++j) {
      if (*roles[k].second != *roles[j].second) continue;
      entry.Child(roles[k].first)
          .Fail("joint '" + *roles[k].second + "' is the section's " + roles[j].first +
                " already; expected a joint of its own for each of plunge, pitch and flap");
    }
  }
  section.semichord = ReadNumber(entry.Child("semichord"), Quantity{"a semichord", Bound::kPositive, "m"});
  section.a = ReadChordPosition(entry.Child("a"), "the elastic axis a");
  section.c = ReadChordPosition(entry.Child("c"), "the flap hinge c");
  section.velocity = ReadNumber(entry.Child("velocity"), Quantity{"a free-stream speed", Bound::kNonNegative, "m/s"});
  OverlayNumber(entry, "span", Quantity{"a span", Bound::kPositive, "m"}, &section.span);
  OverlayNumber(entry, "density", Quantity{"an air density", Bound::kPositive, "kg/m^3"}, &section.density);
  ReadInflowStates(entry, &section.inflow_states);
  return section;
}

// The name of a beam (a link under beams:).
std::string ReadBeamName(const Field& field, const UrdfModel& model) {
  const std::string name = ReadString(field, "the name of a beam (a link under beams:)");
  std::vector<std::string> beams;
  for (const BeamSpec& spec : model.spec.beams) beams.push_back(spec.name);
  if (std::find(beams.begin(), beams.end(), name) == beams.end()) {
    field.Fail(NotFoundMessage("beam", "beams", name, model.name, beams));
  }
  return name;
}

// A unit axis in the beam's section frame (x along the beam), perpendicular to the beam; normalised.
Vec3 ReadSectionAxis(const Field& field, const std::string& what) {
  const Vec3 axis = ReadVec3(field, Quantity{what, Bound::kAny, ""});
  if (!(axis.norm() > 0.0) || std::abs(axis.x()) > kPerpendicular * axis.norm()) {
    field.Fail(field.Text() + " is not a direction across the beam; expected " + what +
               " [0, y, z] in the beam's section frame (x runs along the beam)");
  }
  return axis.normalized();
}

AeroStripSpec ReadStrip(const Field& entry, const std::string& name, const UrdfModel& model) {
  CheckKeys(entry, kStripKeys);
  AeroStripSpec strip;
  strip.name = name;
  for (const char* key : {"beam", "semichord", "a"}) {
    RequireKey(entry, key, "the strip's " + std::string(key) + " (docs/config.md, \"aero\")");
  }
  strip.beam = ReadBeamName(entry.Child("beam"), model);
  strip.semichord = ReadNumber(entry.Child("semichord"), Quantity{"a semichord", Bound::kPositive, "m"});
  strip.a = ReadChordPosition(entry.Child("a"), "the elastic axis (beam axis) a");
  if (entry.Child("chord_axis").present()) {
    strip.chord_axis = ReadSectionAxis(entry.Child("chord_axis"), "a chord axis (leading to trailing edge)");
  }
  if (entry.Child("normal_axis").present()) {
    strip.normal_axis = ReadSectionAxis(entry.Child("normal_axis"), "a chord normal (the lift direction)");
  }
  if (std::abs(strip.chord_axis.dot(strip.normal_axis)) > kPerpendicular) {
    const Field field = entry.Child("normal_axis").present() ? entry.Child("normal_axis") : entry.Child("chord_axis");
    field.Fail(field.Text() + " is not perpendicular to the chord axis; expected chord_axis and normal_axis at " +
               "right angles in the section frame");
  }
  ReadInflowStates(entry, &strip.inflow_states);
  const Field flap = entry.Child("flap");
  if (flap.present()) {
    CheckKeys(flap, kFlapKeys);
    for (const char* key : {"beam", "c"}) {
      RequireKey(flap, key, "the flap's " + std::string(key) + " (docs/config.md, \"aero\")");
    }
    strip.flap.beam = ReadBeamName(flap.Child("beam"), model);
    if (strip.flap.beam == strip.beam) {
      flap.Child("beam").Fail(flap.Child("beam").Text() + " carries the strips; expected the control surface's beam");
    }
    strip.flap.c = ReadChordPosition(flap.Child("c"), "the flap hinge c");
  }
  return strip;
}

// A rotor's inflow (docs/config.md, "aero"); its strips are checked against aero.strips when the model is
// built.
AeroRotorSpec ReadRotor(const Field& entry, const std::string& name) {
  CheckKeys(entry, kRotorKeys);
  AeroRotorSpec rotor;
  rotor.name = name;
  for (const char* key : {"strips", "radius"}) {
    RequireKey(entry, key, "the rotor's " + std::string(key) + " (docs/config.md, \"aero\")");
  }
  for (const Field& strip :
       ListEntries(entry.Child("strips"), "a list of strip names (under aero.strips): the blades")) {
    rotor.strips.push_back(ReadString(strip, "the name of a strip under aero.strips"));
  }
  if (rotor.strips.empty()) {
    entry.Child("strips").Fail("lists no strip; expected the names of the blades' strips under aero.strips");
  }
  rotor.radius = ReadNumber(entry.Child("radius"), Quantity{"a rotor radius", Bound::kPositive, "m"});
  if (entry.Child("axis").present()) {
    const Field axis = entry.Child("axis");
    rotor.axis = ReadVec3(axis, Quantity{"a shaft axis in the world frame (along the thrust)", Bound::kAny, ""});
    if (!(rotor.axis.norm() > 0.0)) {
      axis.Fail(axis.Text() + " has no direction; expected a non-zero shaft axis [x, y, z] in the world frame");
    }
    rotor.axis.normalize();
  }
  if (entry.Child("inflow").present()) {
    rotor.inflow = ReadEnum<AeroRotorSpec::Inflow>(
        entry.Child("inflow"), "rotor inflow",
        {{"uniform", AeroRotorSpec::Inflow::kUniform}, {"harmonic", AeroRotorSpec::Inflow::kHarmonic}});
  }
  OverlayVec3(entry, "center", Quantity{"a disc centre in the world frame (on the shaft axis)", Bound::kAny, "m"},
              &rotor.center);
  return rotor;
}

void ReadFlow(const Field& aero, AeroFlowSpec* flow) {
  OverlayVec3(aero, "free_stream", Quantity{"a free-stream velocity in the world frame", Bound::kAny, "m/s"},
              &flow->free_stream);
  OverlayNumber(aero, "density", Quantity{"an air density", Bound::kPositive, "kg/m^3"}, &flow->density);
  const Field gust = aero.Child("gust");
  if (!gust.present()) return;
  CheckKeys(gust, kGustKeys);
  RequireKey(gust, "velocity", "the gust's velocity in the world frame (docs/config.md, \"aero\")");
  flow->gust = ReadVec3(gust.Child("velocity"), Quantity{"a gust velocity in the world frame", Bound::kAny, "m/s"});
  if (gust.Child("scale").present()) {
    flow->gust_scale = ReadTimeFunction(gust.Child("scale"), "", Measure{false, "a gust scale factor"});
  }
}
}  // namespace

void ReadAero(const Field& aero, UrdfModel* model) {
  if (!aero.present()) return;
  CheckKeys(aero, kAeroKeys);
  const Field sections = aero.Child("sections");
  for (const std::string& name : MapKeys(sections, "a map from section names to typical sections")) {
    model->spec.aero_sections.push_back(ReadSection(sections.Child(name), name, *model));
  }
  const Field strips = aero.Child("strips");
  for (const std::string& name : MapKeys(strips, "a map from strip names to strips along beams")) {
    model->spec.aero_strips.push_back(ReadStrip(strips.Child(name), name, *model));
  }
  const Field rotors = aero.Child("rotors");
  for (const std::string& name : MapKeys(rotors, "a map from rotor names to rotors (their blades' strips)")) {
    model->spec.aero_rotors.push_back(ReadRotor(rotors.Child(name), name));
  }
  ReadFlow(aero, &model->spec.aero_flow);
}

void CheckAirspeedSweep(const Field& root, const ModelSpec& spec) {
  if (spec.solver.eigen.sweep_airspeed.empty()) return;
  const Field sweep = root.Child("solver").Child("eigen").Child("sweep").Child("airspeed");
  if (spec.aero_sections.empty() && spec.aero_strips.empty()) {
    sweep.Fail("sweeps the free-stream speed of the aero sections and strips, but there are none; expected "
               "aero.sections or aero.strips (docs/config.md, \"aero\") or a sweep of velocity_scale");
  }
  if (!spec.aero_strips.empty() && !(spec.aero_flow.free_stream.norm() > 0.0)) {
    sweep.Fail("sweeps the strips' free-stream speed along aero.free_stream, which is zero; expected "
               "aero.free_stream to give the stream's direction");
  }
}

}  // namespace io
}  // namespace flexmbd
