#include "flexmbd/io/loop_closure.hpp"

#include <algorithm>
#include <map>
#include <vector>

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
constexpr double kClosureDifferenceStep = 1.0e-7;

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
      const Eigen::VectorXd dq = Eigen::VectorXd::Unit(n, k) * kClosureDifferenceStep;
      J.col(k) = (PoseError(kinematics, q + dq, R_JpJc, p_JpJc) - PoseError(kinematics, q - dq, R_JpJc, p_JpJc)) /
                 (2.0 * kClosureDifferenceStep);
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

// What the fit of one closing joint leaves, on the bodies as placed.
struct ClosureFit {
  Eigen::VectorXd position, velocity;  // the joint's variables and rates
  Vec6 pose_gap = Vec6::Zero();        // rotation vector [rad] and offset [m] of Jc from where the joint puts it
  Vec6 motion_gap = Vec6::Zero();      // angular [rad/s] and linear [m/s] velocity of Jc across what it allows
  double size = 1.0;                   // the scale of the pose gap's tolerance [m]
  double motion_size = 0.0;            // the scale of the motion gap's: the relative motion fitted
};

ClosureFit Fit(const std::map<std::string, FrameMotion>& motion_of, const JointSpec& joint) {
  const FrameMotion P = joint.parent.empty() ? FrameMotion{} : motion_of.at(joint.parent);
  const FrameMotion& C = motion_of.at(joint.child);
  const FrameMotion Jp = CarryRigidly(P, joint.R_PJ, joint.p_PJ);
  const FrameMotion Jc = CarryRigidly(C, joint.R_CJ, joint.p_CJ);
  const JointKinematics kinematics = MakeJointKinematics(joint);
  ClosureFit fit;
  fit.position = FitVariables(kinematics, Jp.R_WF.transpose() * Jc.R_WF, Jp.R_WF.transpose() * (Jc.p_WF - Jp.p_WF),
                              &fit.pose_gap);
  fit.size = 1.0 + Jp.p_WF.norm() + Jc.p_WF.norm();
  // ChildMotion's velocity relations solved for the relative motion, in Jp
  Vec6 relative;
  relative << Jp.R_WF.transpose() * (Jc.w_WF_W - Jp.w_WF_W),
      Jp.R_WF.transpose() * (Jc.v_WFo_W - Jp.v_WFo_W - Jp.w_WF_W.cross(Jc.p_WF - Jp.p_WF));
  if (!kinematics.rotation_constrained) relative.head<3>().setZero();
  fit.motion_size = relative.norm();
  const Jacobian map = RateMap(kinematics, fit.position);
  fit.velocity = kinematics.num_variables == 0 ? Eigen::VectorXd()
                                               : Eigen::VectorXd(map.colPivHouseholderQr().solve(relative));
  fit.motion_gap = relative - map * fit.velocity;  // a 6 x 0 map (spherical, fixed) gives zero
  return fit;
}

std::map<std::string, FrameMotion> PlacedMotions(const ModelSpec& spec) {
  std::map<std::string, FrameMotion> motion_of;
  for (const BodySpec& body : spec.bodies) motion_of[body.name] = MotionOf(body);
  for (const BeamSpec& beam : spec.beams) motion_of[beam.name] = MotionOf(beam);
  return motion_of;
}

void Close(const std::string& source, const std::map<std::string, FrameMotion>& motion_of, JointSpec* joint) {
  const ClosureFit fit = Fit(motion_of, *joint);
  const std::string where = source + ": closures." + joint->name + ": ";
  if (fit.pose_gap.norm() > kClosingTolerance * fit.size) {
    throw ConfigError(where + "the loop does not close: the child's joint frame lies " + Offsets(fit.pose_gap) +
                      " (in the parent's joint frame) from where the " + JointTypeName(joint->type) +
                      " joint can put it; expected initial positions and drives at t = 0 of the URDF joints that "
                      "let the loops close (the loader moves the joints not set to close them)");
  }
  const Vec6& opening = fit.motion_gap;
  if (opening.norm() > kClosingTolerance * std::max(1.0, fit.motion_size)) {
    throw ConfigError(where + "the initial motion opens the loop: relative to the parent's joint frame the child "
                      "moves at " + FormatVector(opening.tail<3>()) + " m/s and turns at " +
                      FormatVector(opening.head<3>()) + " rad/s across what the " + JointTypeName(joint->type) +
                      " joint allows; expected initial rates of the URDF joints that let the loops close (the "
                      "loader moves the rates not set to close them)");
  }
  joint->initial_position.assign(fit.position.data(), fit.position.data() + fit.position.size());
  joint->initial_velocity.assign(fit.velocity.data(), fit.velocity.data() + fit.velocity.size());
}

template <class GapOf>
Eigen::VectorXd Gaps(const ModelSpec& spec, GapOf gap_of) {
  const std::map<std::string, FrameMotion> motion_of = PlacedMotions(spec);
  std::vector<Vec6> gaps;
  for (const JointSpec& joint : spec.joints) {
    if (joint.closes_loop) gaps.push_back(gap_of(Fit(motion_of, joint)));
  }
  Eigen::VectorXd all(6 * gaps.size());
  for (size_t i = 0; i < gaps.size(); ++i) all.segment<6>(6 * i) = gaps[i];
  return all;
}
}  // namespace

Eigen::VectorXd LoopPoseGaps(const ModelSpec& spec) {
  return Gaps(spec, [](const ClosureFit& fit) { return fit.pose_gap; });
}

Eigen::VectorXd LoopMotionGaps(const ModelSpec& spec) {
  return Gaps(spec, [](const ClosureFit& fit) { return fit.motion_gap; });
}

void CloseLoops(const std::string& source, ModelSpec* spec) {
  const std::map<std::string, FrameMotion> motion_of = PlacedMotions(*spec);
  for (JointSpec& joint : spec->joints) {
    if (joint.closes_loop) Close(source, motion_of, &joint);
  }
}

}  // namespace io
}  // namespace flexmbd
