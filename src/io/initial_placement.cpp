#include "flexmbd/io/initial_placement.hpp"

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/joints/joint_kinematics.hpp"

namespace flexmbd {
namespace io {
namespace {
// Places bodies on demand, parents first (the joint tree may list children before parents).
class Placer {
 public:
  Placer(const std::vector<BodyMount>& free_bodies, ModelSpec* spec) : spec_(spec) {
    for (size_t i = 0; i < spec->bodies.size(); ++i) body_index_[spec->bodies[i].name] = i;
    for (size_t i = 0; i < spec->beams.size(); ++i) beam_index_[spec->beams[i].name] = i;
    for (const JointSpec& joint : spec->joints) {
      if (joint.closes_loop) continue;  // CloseLoops attaches it to its placed child
      FLEXMBD_DEMAND(body_index_.count(joint.child) + beam_index_.count(joint.child) == 1 &&
                     mount_of_.count(joint.child) == 0);
      mount_of_[joint.child] = Mount{&joint, nullptr};
    }
    for (const BodyMount& mount : free_bodies) {
      FLEXMBD_DEMAND(body_index_.count(mount.body) + beam_index_.count(mount.body) == 1 &&
                     mount_of_.count(mount.body) == 0);
      mount_of_[mount.body] = Mount{nullptr, &mount};
    }
  }

  void PlaceAll() {
    for (const BodySpec& body : spec_->bodies) Place(body.name);
    for (const BeamSpec& beam : spec_->beams) Place(beam.name);
  }

 private:
  struct Mount {
    const JointSpec* joint;
    const BodyMount* free;
  };

  // Places `body` and the unplaced bodies it hangs from, top down. Iterative: a chain may be tens of
  // thousands of bodies deep.
  void Place(const std::string& body) {
    std::vector<std::string> unplaced;  // from `body` up to a placed body or the ground
    for (std::string link = body; !link.empty() && !placed_.count(link); link = ParentOf(link)) {
      // each body hangs from exactly one mount, so the walk up reaches the ground before it repeats a body
      FLEXMBD_DEMAND(unplaced.size() < mount_of_.size());
      unplaced.push_back(link);
    }
    for (auto link = unplaced.rbegin(); link != unplaced.rend(); ++link) PlaceOnParent(*link);
  }

  std::string ParentOf(const std::string& body) const {
    const Mount& mount = mount_of_.at(body);
    return mount.joint ? mount.joint->parent : mount.free->parent;
  }

  // @pre the parent of `body` is placed (or is the ground)
  void PlaceOnParent(const std::string& body) {
    const Mount& mount = mount_of_.at(body);
    const std::string parent = ParentOf(body);
    const FrameMotion parent_motion = parent.empty() ? FrameMotion{} : placed_.at(parent);
    const FrameMotion motion = mount.joint ? ChildMotion(parent_motion, *mount.joint)
                                           : CarryRigidly(parent_motion, mount.free->R_PB, mount.free->p_PB);
    const auto rigid = body_index_.find(body);
    if (rigid != body_index_.end()) {
      SetPose(motion, &spec_->bodies[rigid->second]);
    } else {
      SetPose(motion, &spec_->beams[beam_index_.at(body)]);
    }
    placed_[body] = motion;
  }

  // Bodies and beams carry the same initial pose and velocity fields of their link frame.
  template <class LinkSpec>
  static void SetPose(const FrameMotion& motion, LinkSpec* spec) {
    spec->R_WB = motion.R_WF;
    spec->p_WB = motion.p_WF;
    spec->v_WBo_W = motion.v_WFo_W;
    spec->w_WB_W = motion.w_WF_W;
  }

  ModelSpec* spec_;
  std::map<std::string, size_t> body_index_, beam_index_;
  std::map<std::string, Mount> mount_of_;
  std::map<std::string, FrameMotion> placed_;
};
}  // namespace

FrameMotion CarryRigidly(const FrameMotion& P, const Mat3& R_PF, const Vec3& p_PF) {
  FrameMotion F;
  F.R_WF = P.R_WF * R_PF;
  F.p_WF = P.p_WF + P.R_WF * p_PF;
  F.w_WF_W = P.w_WF_W;
  F.v_WFo_W = P.v_WFo_W + P.w_WF_W.cross(F.p_WF - P.p_WF);
  return F;
}

FrameMotion ChildMotion(const FrameMotion& P, const JointSpec& joint) {
  const JointKinematics kinematics = MakeJointKinematics(joint);
  const Eigen::VectorXd q =
      Eigen::Map<const Eigen::VectorXd>(joint.initial_position.data(), joint.initial_position.size());
  const Eigen::VectorXd qdot =
      Eigen::Map<const Eigen::VectorXd>(joint.initial_velocity.data(), joint.initial_velocity.size());
  Mat3 R_JpJc;
  Vec3 p_JpJc_Jp, w_JpJc_Jp, v_JpJc_Jp;
  RelativePose(kinematics, q, &R_JpJc, &p_JpJc_Jp);
  RelativeVelocity(kinematics, q, qdot, &w_JpJc_Jp, &v_JpJc_Jp);
  R_JpJc = joint.initial_rotation * R_JpJc;  // identity and zero but on a spherical joint
  w_JpJc_Jp += joint.initial_angular_velocity;

  const FrameMotion Jp = CarryRigidly(P, joint.R_PJ, joint.p_PJ);
  FrameMotion Jc;
  Jc.R_WF = Jp.R_WF * R_JpJc;
  Jc.p_WF = Jp.p_WF + Jp.R_WF * p_JpJc_Jp;
  Jc.w_WF_W = Jp.w_WF_W + Jp.R_WF * w_JpJc_Jp;
  Jc.v_WFo_W = Jp.v_WFo_W + Jp.w_WF_W.cross(Jp.R_WF * p_JpJc_Jp) + Jp.R_WF * v_JpJc_Jp;
  return CarryRigidly(Jc, joint.R_CJ.transpose(), -(joint.R_CJ.transpose() * joint.p_CJ));
}

void PlaceBodies(const std::vector<BodyMount>& free_bodies, ModelSpec* spec) { Placer(free_bodies, spec).PlaceAll(); }

}  // namespace io
}  // namespace flexmbd
