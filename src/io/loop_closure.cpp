#include "flexmbd/io/loop_closure.hpp"

#include <map>

#include <Eigen/QR>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/initial_placement.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/joints/joint_kinematics.hpp"
#include "flexmbd/math/so3.hpp"

namespace flexmbd {
namespace io {
namespace {
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic>;

// What a fit of the variables (or rates) leaves is round-off when the loop closes: relative to the length of
// the loop's frames from the origin (metres; radians count as metres on a 1 m lever), or to the motion fitted.
constexpr double kClosingTolerance = 1.0e-9;
// Gauss-Newton on the variables: the rotation factors make the pose nonlinear in them; it converges in a few
// iterations from q = 0 when the frames are apart by the joint's own motion.
constexpr int kFitIterations = 50;
constexpr double kDifferenceStep = 1.0e-7;

template <class LinkSpec>
FrameMotion MotionOf(const LinkSpec& link) {
  return FrameMotion{link.R_WB, link.p_WB, link.v_WBo_W, link.w_WB_W};
}

// The pose of the child frame relative to where the joint at q puts it: rotation vector and offset, in Jp;
// the rotation is free in a joint that leaves it so (spherical).
Vec6 PoseError(const JointKinematics& kinematics, const Eigen::VectorXd& q, const Mat3& R_JpJc, const Vec3& p_JpJc) {
  Mat3 R;
  Vec3 p;
  RelativePose(kinematics, q, &R, &p);
  Vec6 error;
  error << (kinematics.rotation_constrained ? Vec3(R * Log(R.transpose() * R_JpJc)) : Vec3::Zero()), p_JpJc - p;
  return error;
}

// Least-squares variables of the relative pose (R_JpJc, p_JpJc); `left` is the error that remains.
Eigen::VectorXd FitVariables(const JointKinematics& kinematics, const Mat3& R_JpJc, const Vec3& p_JpJc, Vec6* left) {
  const int n = kinematics.num_variables;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
  *left = PoseError(kinematics, q, R_JpJc, p_JpJc);
  for (int iteration = 0; iteration < kFitIterations && n > 0; ++iteration) {
    Jacobian J(6, n);
    for (int k = 0; k < n; ++k) {
      const Eigen::VectorXd dq = Eigen::VectorXd::Unit(n, k) * kDifferenceStep;
      J.col(k) = (PoseError(kinematics, q + dq, R_JpJc, p_JpJc) - PoseError(kinematics, q - dq, R_JpJc, p_JpJc)) /
                 (2.0 * kDifferenceStep);
    }
    const Eigen::VectorXd step = J.colPivHouseholderQr().solve(-*left);
    q += step;
    *left = PoseError(kinematics, q, R_JpJc, p_JpJc);
    if (step.norm() < 1e-15 * (1.0 + q.norm())) break;
  }
  return q;
}

// The relative angular and linear velocity of the joint frame as a linear map of the rates at q.
Jacobian RateMap(const JointKinematics& kinematics, const Eigen::VectorXd& q) {
  Jacobian map(6, kinematics.num_variables);
  for (int k = 0; k < kinematics.num_variables; ++k) {
    Vec3 w, v;
    RelativeVelocity(kinematics, q, Eigen::VectorXd::Unit(kinematics.num_variables, k), &w, &v);
    map.col(k) << w, v;
  }
  return map;
}

std::string Offsets(const Vec6& left) {
  return FormatVector(left.tail<3>()) + " m and " + FormatVector(left.head<3>()) + " rad";
}

void Close(const std::string& source, const std::map<std::string, FrameMotion>& motion_of, JointSpec* joint) {
  const FrameMotion P = joint->parent.empty() ? FrameMotion{} : motion_of.at(joint->parent);
  const FrameMotion& C = motion_of.at(joint->child);
  const FrameMotion Jp = CarryRigidly(P, joint->R_PJ, joint->p_PJ);
  const FrameMotion Jc = CarryRigidly(C, joint->R_CJ, joint->p_CJ);
  const std::string where = source + ": closures." + joint->name + ": ";
  const JointKinematics kinematics = MakeJointKinematics(*joint);

  Vec6 left;
  const Eigen::VectorXd q =
      FitVariables(kinematics, Jp.R_WF.transpose() * Jc.R_WF, Jp.R_WF.transpose() * (Jc.p_WF - Jp.p_WF), &left);
  const double size = 1.0 + Jp.p_WF.norm() + Jc.p_WF.norm();
  if (left.norm() > kClosingTolerance * size) {
    throw ConfigError(where + "the loop does not close: the child's joint frame lies " + Offsets(left) +
                      " (in the parent's joint frame) from where the " + JointTypeName(joint->type) +
                      " joint can put it; expected child_xyz and child_rpy (the joint frame in the child link) at "
                      "the parent's joint frame as the URDF places the links");
  }
  // ChildMotion's velocity relations solved for the relative motion, in Jp
  Vec6 relative;
  relative << Jp.R_WF.transpose() * (Jc.w_WF_W - Jp.w_WF_W),
      Jp.R_WF.transpose() * (Jc.v_WFo_W - Jp.v_WFo_W - Jp.w_WF_W.cross(Jc.p_WF - Jp.p_WF));
  if (!kinematics.rotation_constrained) relative.head<3>().setZero();
  const Jacobian map = RateMap(kinematics, q);
  const Eigen::VectorXd rates =
      kinematics.num_variables == 0 ? Eigen::VectorXd() : Eigen::VectorXd(map.colPivHouseholderQr().solve(relative));
  const Vec6 opening = relative - map * rates;  // a 6 x 0 map (spherical, fixed) gives zero
  if (opening.norm() > kClosingTolerance * std::max(1.0, relative.norm())) {
    throw ConfigError(where + "the initial motion opens the loop: relative to the parent's joint frame the child "
                      "moves at " + FormatVector(opening.tail<3>()) + " m/s and turns at " +
                      FormatVector(opening.head<3>()) + " rad/s across what the " + JointTypeName(joint->type) +
                      " joint allows; expected initial rates of the URDF joints that keep the loop closed");
  }
  joint->initial_position.assign(q.data(), q.data() + q.size());
  joint->initial_velocity.assign(rates.data(), rates.data() + rates.size());
}
}  // namespace

void CloseLoops(const std::string& source, ModelSpec* spec) {
  std::map<std::string, FrameMotion> motion_of;
  for (const BodySpec& body : spec->bodies) motion_of[body.name] = MotionOf(body);
  for (const BeamSpec& beam : spec->beams) motion_of[beam.name] = MotionOf(beam);
  for (JointSpec& joint : spec->joints) {
    if (joint.closes_loop) Close(source, motion_of, &joint);
  }
}

}  // namespace io
}  // namespace flexmbd
