// `closures:` joints that close kinematic loops, which a URDF (a tree) cannot hold (docs/config.md, "closures").

#include <Eigen/Geometry>

#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/urdf_tree.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
const std::vector<std::string> kClosureKeys = {"type", "parent", "child", "xyz", "rpy", "child_xyz", "child_rpy",
                                               "axis", "axis2", "pitch"};

// Roll, pitch and yaw about the fixed x, y and z axes, as a URDF <origin rpy>.
Mat3 FromRollPitchYaw(const Vec3& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

// The joint frame on a link's body from `<prefix>xyz` and `<prefix>rpy`, in the link's frame (default: the
// link's frame itself, as a URDF joint's child frame).
void PlaceJointFrame(const Field& entry, const std::string& prefix, const LinkFrame& link, Mat3* R_BJ, Vec3* p_BJ) {
  const std::string side = prefix.empty() ? "parent" : "child";
  Vec3 xyz = Vec3::Zero(), rpy = Vec3::Zero();
  OverlayVec3(entry, prefix + "xyz", Quantity{"the joint origin in the " + side + " link's frame", Bound::kAny, "m"},
              &xyz);
  OverlayVec3(entry, prefix + "rpy",
              Quantity{"roll, pitch and yaw of the joint frame in the " + side + " link's frame", Bound::kAny, "rad"},
              &rpy);
  *p_BJ = link.p + link.R * xyz;
  *R_BJ = link.R * FromRollPitchYaw(rpy);
}

const LinkFrame& ReadLink(const Field& field, const UrdfModel& model, const std::string& what) {
  const std::string name = ReadString(field, "the name of the " + what + " link (a URDF link)");
  const auto frame = model.link_frames.find(name);
  if (frame != model.link_frames.end()) return frame->second;
  std::vector<std::string> names;
  for (const auto& [link, unused] : model.link_frames) names.push_back(link);
  field.Fail(NotFoundMessage("link", "links", name, model.name, names));
}

void CheckNewName(const Field& entry, const std::string& name, const UrdfModel& model) {
  const std::string problem = CsvNameProblem(name);
  if (!problem.empty()) {
    entry.Fail("the name contains " + problem + "; expected a name without commas, double quotes or control "
               "characters (names head the CSV columns)");
  }
  bool taken = model.frame_joints.count(name) > 0;
  for (const JointSpec& joint : model.spec.joints) taken = taken || joint.name == name;
  if (taken) entry.Fail("a joint of that name exists already; expected a new joint name");
}

JointSpec ReadClosure(const Field& entry, const std::string& name, const UrdfModel& model) {
  CheckKeys(entry, kClosureKeys);
  CheckNewName(entry, name, model);
  for (const char* key : {"type", "parent", "child"}) {
    RequireKey(entry, key, "the closing joint's " + std::string(key) + " (docs/config.md, \"closures\")");
  }
  const LinkFrame& parent = ReadLink(entry.Child("parent"), model, "parent");
  const LinkFrame& child = ReadLink(entry.Child("child"), model, "child");
  if (child.body.empty()) {
    entry.Child("child").Fail("link '" + entry.Child("child").Text() +
                              "' is fixed to the ground; expected a link that moves (the ground goes as the parent)");
  }
  if (child.body == parent.body) {
    entry.Fail("parent and child are both on '" + child.body + "'; expected links of two different bodies");
  }
  JointSpec joint;
  joint.name = name;
  joint.closes_loop = true;
  joint.parent = parent.body;
  joint.child = child.body;
  PlaceJointFrame(entry, "", parent, &joint.R_PJ, &joint.p_PJ);
  PlaceJointFrame(entry, "child_", child, &joint.R_CJ, &joint.p_CJ);
  joint.axis_J = Vec3::UnitX();  // a URDF joint's default axis
  ReadJointGeometry(entry, &joint);
  return joint;
}
}  // namespace

void ReadClosures(const Field& closures, UrdfModel* model) {
  for (const std::string& name : MapKeys(closures, "a map from joint names to joints that close loops")) {
    model->spec.joints.push_back(ReadClosure(closures.Child(name), name, *model));
  }
}

}  // namespace io
}  // namespace flexmbd
