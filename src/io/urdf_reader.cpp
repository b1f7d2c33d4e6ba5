#include "flexmbd/io/urdf_reader.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <memory>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/joint_axes.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/urdf_pose.hpp"
#include "flexmbd/io/urdf_tree.hpp"
#include "flexmbd/joints/joint_kinematics.hpp"

namespace flexmbd {
namespace io {
namespace {
// Relative tolerance on a negative principal moment of inertia: URDF values are printed with few digits,
// so an inertia on the boundary of the PSD cone may come out as -1e-12 of the largest moment.
constexpr double kInertiaTolerance = 1.0e-9;

// Collects urdfdom's error messages (console_bridge) while it parses; the previous handler is restored on
// destruction. console_bridge keeps one global handler, so parsing is not thread-safe anyway.
class UrdfdomErrors : public console_bridge::OutputHandler {
 public:
  UrdfdomErrors() { console_bridge::useOutputHandler(this); }
  ~UrdfdomErrors() override { console_bridge::restorePreviousOutputHandler(); }
  UrdfdomErrors(const UrdfdomErrors&) = delete;
  UrdfdomErrors& operator=(const UrdfdomErrors&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      std::string line = text;
      for (char& c : line) c = c == '\n' ? ' ' : c;
      messages_ += (messages_.empty() ? "" : "; ") + line;
    }
  }
  const std::string& messages() const { return messages_; }

 private:
  std::string messages_;
};

urdf::ModelInterfaceSharedPtr ParseUrdf(const std::string& urdf_xml, const std::string& urdf_name) {
  std::string errors;
  urdf::ModelInterfaceSharedPtr model;
  {
    UrdfdomErrors log;
    model = urdf::parseURDF(urdf_xml);
    errors = log.messages();
  }
  // urdfdom may log an error and still return a model (e.g. an <inertial> without <inertia>): reject both
  if (!model || !errors.empty()) {
    throw ConfigError(urdf_name + ": not a valid URDF (urdfdom could not parse it)" +
                      (errors.empty() ? "" : ": " + errors));
  }
  return model;
}

// Builds the model by walking the URDF tree from its root.
class UrdfWalker {
 public:
  UrdfWalker(const urdf::ModelInterface& urdf, const std::string& name, const std::set<std::string>& beam_links)
      : urdf_(urdf), beam_links_(beam_links) {
    model_.name = name;
  }

  UrdfModel Walk() {
    const urdf::Link& root = *urdf_.getRoot();
    AddRoot(root);
    AddTree(root);
    if (model_.spec.bodies.empty() && model_.spec.beams.empty()) FailNothingMoves(root);
    return std::move(model_);
  }

 private:
  void AddRoot(const urdf::Link& root) {
    if (beam_links_.count(root.name)) {
      AddBeam(root);
      model_.free_bodies.push_back(BodyMount{root.name, "", Mat3::Identity(), Vec3::Zero()});
      return;
    }
    if (root.name == "world" || !root.inertial) {
      model_.link_frames[root.name] = LinkFrame{};
      return;
    }
    model_.spec.bodies.push_back(MakeBody(root));
    model_.free_bodies.push_back(BodyMount{root.name, "", Mat3::Identity(), Vec3::Zero()});
    model_.link_frames[root.name] = LinkFrame{root.name};
  }

  // Depth first, each link's joints in URDF order (the order of the joints, and of their CSV columns), with a
  // stack of joints rather than recursion: a chain may be tens of thousands of links deep.
  void AddTree(const urdf::Link& root) {
    std::vector<const urdf::Joint*> to_add;
    auto push_children = [&to_add](const urdf::Link& link) {
      for (auto joint = link.child_joints.rbegin(); joint != link.child_joints.rend(); ++joint) {
        to_add.push_back(joint->get());
      }
    };
    push_children(root);
    while (!to_add.empty()) {
      const urdf::Joint& joint = *to_add.back();
      to_add.pop_back();
      const urdf::Link& child = *urdf_.links_.at(joint.child_link_name);
      AddJoint(joint, child, model_.link_frames.at(joint.parent_link_name));
      push_children(child);
    }
  }

  // A model with no body and no beam has no unknowns: the solver would have nothing to solve.
  [[noreturn]] void FailNothingMoves(const urdf::Link& root) const {
    Fail("nothing can move: root link '" + root.name + "' is the ground and " +
         (urdf_.links_.size() == 1 ? std::string("there is no other link")
                                   : "every other link is fixed to it as a frame (no <inertial>)") +
         "; expected at least one link with <inertial> (or named under beams:) below a joint");
  }

  void AddJoint(const urdf::Joint& joint, const urdf::Link& child, const LinkFrame& parent) {
    // the joint frame on the parent body
    const urdf::Pose& origin = joint.parent_to_joint_origin_transform;
    const LinkFrame joint_frame{parent.body, parent.R * ToMat3(origin.rotation),
                                parent.p + parent.R * ToVec3(origin.position)};
    const bool beam = beam_links_.count(child.name) > 0;
    if (joint.type == urdf::Joint::FIXED && !child.inertial && !beam) {
      model_.link_frames[child.name] = joint_frame;
      model_.frame_joints[joint.name] = "it fixes link '" + child.name + "', which has no <inertial>, as a frame on " +
                                        (parent.body.empty() ? "the ground" : "body '" + parent.body + "'");
      return;
    }
    if (!child.inertial && !beam) {
      Fail("link '" + child.name + "' moves (joint '" + joint.name +
           "') but has no <inertial>; expected mass and inertia");
    }
    if (beam) {
      AddBeam(child);
    } else {
      model_.spec.bodies.push_back(MakeBody(child));
      model_.link_frames[child.name] = LinkFrame{child.name};
    }
    if (joint.type == urdf::Joint::FLOATING) {
      model_.free_bodies.push_back(BodyMount{child.name, parent.body, joint_frame.R, joint_frame.p});
      model_.frame_joints[joint.name] = "it is a floating joint: link '" + child.name + "' is a free body";
      return;
    }
    model_.spec.joints.push_back(MakeJoint(joint, child.name, joint_frame));
  }

  // A link named under `beams:`: the YAML gives its length, elements and section.
  void AddBeam(const urdf::Link& link) {
    BeamSpec beam;
    beam.name = link.name;
    model_.spec.beams.push_back(beam);
    model_.link_frames[link.name] = LinkFrame{link.name};
  }

  BodySpec MakeBody(const urdf::Link& link) const {
    const urdf::Inertial& inertial = *link.inertial;
    if (!(inertial.mass > 0.0) || !std::isfinite(inertial.mass)) {
      Fail("link '" + link.name + "': mass " + FormatNumber(inertial.mass) +
           " is not positive; expected a mass > 0 [kg]");
    }
    Mat3 inertia_I;
    inertia_I << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz, inertial.ixz,
        inertial.iyz, inertial.izz;
    CheckInertia(link.name, inertia_I);
    const Mat3 R_BI = ToMat3(inertial.origin.rotation);
    BodySpec body;
    body.name = link.name;
    body.mass = inertial.mass;
    body.inertia_cm_B = R_BI * inertia_I * R_BI.transpose();
    body.p_BoBcm_B = ToVec3(inertial.origin.position);
    return body;
  }

  void CheckInertia(const std::string& link, const Mat3& inertia) const {
    const Vec3 moments = Eigen::SelfAdjointEigenSolver<Mat3>(inertia, Eigen::EigenvaluesOnly).eigenvalues();
    if (!inertia.allFinite() || moments.minCoeff() < -kInertiaTolerance * moments.cwiseAbs().maxCoeff()) {
      Fail("link '" + link + "': <inertia> has principal moments " + FormatVector(moments) +
           "; expected a positive semi-definite inertia [kg m^2]");
    }
    // A body's principal moments are integrals of y^2 + z^2 and the like, so none exceeds the sum of the other two;
    // inertia beyond that is not a body's, and a dynamic run would take it without a word.
    if (moments[2] > moments[0] + moments[1] + kInertiaTolerance * moments[2]) {
      Fail("link '" + link + "': <inertia> has principal moments " + FormatVector(moments) +
           "; expected each principal moment at most the sum of the other two (the triangle inequality of a body's "
           "inertia) [kg m^2]");
    }
  }

  JointSpec MakeJoint(const urdf::Joint& urdf_joint, const std::string& child, const LinkFrame& joint_frame) const {
    JointSpec joint;
    joint.name = urdf_joint.name;
    joint.type = TypeOf(urdf_joint);
    joint.parent = joint_frame.body;
    joint.child = child;
    joint.p_PJ = joint_frame.p;
    joint.R_PJ = joint_frame.R;
    joint.axis_J = ToVec3(urdf_joint.axis);
    joint.axis2_J = DefaultSecondAxis(joint.axis_J);
    ResizeJointVariables(&joint);
    AddUrdfDynamics(urdf_joint, &joint);
    ReadUrdfLimits(urdf_joint, &joint);
    try {
      MakeJointKinematics(joint);
    } catch (const ConfigError& error) {
      Fail(error.what());
    }
    return joint;
  }

  JointType TypeOf(const urdf::Joint& joint) const {
    switch (joint.type) {
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS: return JointType::kRevolute;
      case urdf::Joint::PRISMATIC: return JointType::kPrismatic;
      case urdf::Joint::PLANAR: return JointType::kPlanar;
      case urdf::Joint::FIXED: return JointType::kFixed;
      default: break;
    }
    Fail("joint '" + joint.name +
         "': unsupported type; expected revolute, continuous, prismatic, planar, fixed or floating");
  }

  // <dynamics damping> becomes a damper on variable 0, <dynamics friction> a friction of constant bound (a
  // YAML friction block replaces it).
  void AddUrdfDynamics(const urdf::Joint& urdf_joint, JointSpec* joint) const {
    if (!urdf_joint.dynamics || joint->effects.empty()) return;
    const double damping = urdf_joint.dynamics->damping;
    if (!(damping >= 0.0) || !std::isfinite(damping)) {
      const char* unit = joint->type == JointType::kPrismatic ? "N s/m" : "N m s/rad";
      Fail("joint '" + joint->name + "': <dynamics damping> " + FormatNumber(damping) +
           " is negative; expected a damping >= 0 [" + unit + "]");
    }
    if (damping > 0.0) joint->effects[0].dampers = {DamperSpec{damping}};
    const double friction = urdf_joint.dynamics->friction;
    if (!(friction >= 0.0) || !std::isfinite(friction)) {
      const char* unit = joint->type == JointType::kPrismatic ? "N" : "N m";
      Fail("joint '" + joint->name + "': <dynamics friction> " + FormatNumber(friction) +
           " is negative; expected a friction >= 0 [" + unit + "]");
    }
    if (friction > 0.0) {
      FrictionSpec constant;
      constant.law = FrictionSpec::Law::kConstantTorque;
      constant.torque = friction;
      joint->effects[0].frictions = {constant};
    }
  }

  // <limit> of a revolute or prismatic joint: the stop positions of a backlash block that gives none.
  static void ReadUrdfLimits(const urdf::Joint& urdf_joint, JointSpec* joint) {
    const bool bounded = urdf_joint.type == urdf::Joint::REVOLUTE || urdf_joint.type == urdf::Joint::PRISMATIC;
    if (!bounded || !urdf_joint.limits || !(urdf_joint.limits->lower < urdf_joint.limits->upper)) return;
    joint->has_limits = true;
    joint->limit_lower = urdf_joint.limits->lower;
    joint->limit_upper = urdf_joint.limits->upper;
  }

  [[noreturn]] void Fail(const std::string& what) const { throw ConfigError(model_.name + ": " + what); }

  const urdf::ModelInterface& urdf_;
  const std::set<std::string>& beam_links_;
  UrdfModel model_;
};
}  // namespace

UrdfModel ReadUrdf(const std::string& urdf_xml, const std::string& urdf_name,
                   const std::set<std::string>& beam_links, const std::string& beam_links_file) {
  const UrdfTreeOwner urdf(ParseUrdf(urdf_xml, urdf_name));
  CheckUrdfTree(*urdf, urdf_name);
  for (const std::string& beam : beam_links) {
    if (!urdf->getLink(beam)) {
      std::vector<std::string> links;
      for (const auto& link : urdf->links_) links.push_back(link.first);
      throw ConfigError(QuoteForMessage(beam_links_file + ": beams." + beam + ": ") +
                        NotFoundMessage("link", "links", beam, urdf_name, links));
    }
  }
  return UrdfWalker(*urdf, urdf_name, beam_links).Walk();
}

void ResizeJointVariables(JointSpec* joint) {
  const size_t n = static_cast<size_t>(NumJointVariables(joint->type));
  joint->initial_position.resize(n, 0.0);
  joint->initial_velocity.resize(n, 0.0);
  joint->effects.resize(n);
  joint->position_set.resize(n, false);
  joint->velocity_set.resize(n, false);
}

}  // namespace io
}  // namespace flexmbd
