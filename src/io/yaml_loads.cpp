#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
const std::vector<std::string> kLoadKeys = {"body", "force", "moment", "frame", "point", "distributed", "scale"};

std::string ReadBodyName(const Field& field, const UrdfModel& model) {
  const std::string name = ReadString(field, "a body or beam name (a URDF link with <inertial>, or under beams:)");
  std::vector<std::string> names;
  for (const BodySpec& body : model.spec.bodies) names.push_back(body.name);
  for (const BeamSpec& beam : model.spec.beams) names.push_back(beam.name);
  for (const std::string& known : names) {
    if (known == name) return name;
  }
  field.Fail(NotFoundMessage("body or beam", "bodies and beams", name, model.name, names));
}

void ReadVector(const Field& entry, LoadSpec* load) {
  const Field force = entry.Child("force");
  const Field moment = entry.Child("moment");
  if (force.present() == moment.present()) {
    entry.Fail(std::string(force.present() ? "gives both 'force' and 'moment'" : "gives neither 'force' nor 'moment'") +
               "; expected exactly one of them");
  }
  load->kind = force.present() ? LoadSpec::Kind::kForce : LoadSpec::Kind::kMoment;
  load->vector = force.present() ? ReadVec3(force, Quantity{"a force", Bound::kAny, "N"})
                                 : ReadVec3(moment, Quantity{"a moment", Bound::kAny, "N m"});
}

bool IsBeam(const UrdfModel& model, const std::string& name) {
  for (const BeamSpec& beam : model.spec.beams) {
    if (beam.name == name) return true;
  }
  return false;
}

// A distributed load is per unit length along a whole beam: no point, and its body must be a beam.
void ReadDistribution(const Field& entry, const UrdfModel& model, const LoadSpec& load) {
  if (entry.Child("point").present()) {
    entry.Child("point").Fail(
        "is given for a distributed load; expected no point (the load is uniform along the beam)");
  }
  if (IsBeam(model, load.body)) return;
  entry.Child("distributed").Fail("true on '" + load.body + "', which is not a beam; expected a link under beams:");
}

// A moment acts on a whole rigid body, so it has no point there; on a beam the point's x picks the node it acts on
// (the tip's moment of a cantilever), and an offset across the beam would have no meaning.
void CheckMomentPoint(const Field& point, const UrdfModel& model, const LoadSpec& load) {
  if (!IsBeam(model, load.body)) {
    point.Fail("applies only to forces, and to moments on beams (where its x picks the node); a moment on the rigid "
               "body '" + load.body + "' has no point of application");
  }
  if (load.p_BoP_B.y() != 0.0 || load.p_BoP_B.z() != 0.0) {
    point.Fail(FormatVector(load.p_BoP_B) + " is off the axis of beam '" + load.body +
               "'; expected [x, 0, 0] for a moment: x picks the node it acts on, and a moment has no lever arm");
  }
}

LoadSpec ReadLoad(const Field& entry, const UrdfModel& model) {
  CheckKeys(entry, kLoadKeys);
  RequireKey(entry, "body", "the name of a body (a URDF link with <inertial>)");
  LoadSpec load;
  load.body = ReadBodyName(entry.Child("body"), model);
  ReadVector(entry, &load);
  if (entry.Child("frame").present()) {
    load.frame = ReadEnum<LoadSpec::Frame>(entry.Child("frame"), "load frame",
                                           {{"world", LoadSpec::Frame::kWorld}, {"body", LoadSpec::Frame::kBody}});
  }
  const Field point = entry.Child("point");
  if (point.present()) {
    load.p_BoP_B = ReadVec3(point, Quantity{"a point in the body frame", Bound::kAny, "m"});
    if (load.kind == LoadSpec::Kind::kMoment) CheckMomentPoint(point, model, load);
  }
  OverlayBool(entry, "distributed", &load.distributed);
  if (load.distributed) ReadDistribution(entry, model, load);
  const Field scale = entry.Child("scale");
  if (scale.present()) load.scale = ReadTimeFunction(scale, "", Measure{false, "a load scale factor"});
  return load;
}
}  // namespace

void ReadLoads(const Field& loads, const UrdfModel& model, std::vector<LoadSpec>* specs) {
  for (const Field& entry : ListEntries(loads, "a list of loads {body, force | moment, frame, point, scale}")) {
    specs->push_back(ReadLoad(entry, model));
  }
}

}  // namespace io
}  // namespace flexmbd
