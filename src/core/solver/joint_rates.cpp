#include "flexmbd/solver/joint_rates.hpp"

#include <Eigen/Dense>

#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace {
// Pose and velocity of a joint frame fixed to a node (or to the world).
struct FrameMotion {
  Vec3 p = Vec3::Zero(), v = Vec3::Zero(), w = Vec3::Zero();  // position, velocity, angular velocity, all in W
  Mat3 R = Mat3::Identity();
};

FrameMotion Motion(const Joint::Attachment& side, const State& state) {
  FrameMotion m;
  if (side.node < 0) {
    m.p = side.p_NJ;
    m.R = side.R_NJ;
    return m;
  }
  const NodeState& n = state.nodes[side.node];
  const Vec3 r = n.R * side.p_NJ;
  m.p = n.x + r;
  m.R = n.R * side.R_NJ;
  m.w = n.R * n.w;
  m.v = n.v + m.w.cross(r);
  return m;
}
}  // namespace

Eigen::VectorXd JointRates(const Model& model, const State& state) {
  Eigen::VectorXd qdot = Eigen::VectorXd::Zero(model.num_variables());
  for (const Joint* joint : model.joints()) {
    const int n = joint->num_variables();
    if (n == 0) continue;
    const FrameMotion p = Motion(joint->parent(), state), c = Motion(joint->child(), state);
    // Relative twist of Jc in Jp, expressed in Jp: w = R^T (w_c - w_p), v = d/dt [R^T (p_c - p_p)].
    const Mat3 Rt = p.R.transpose();
    Eigen::Matrix<double, 6, 1> twist;
    twist.head<3>() = Rt * (c.w - p.w);
    twist.tail<3>() = Rt * (c.v - p.v) - (Rt * p.w).cross(Rt * (c.p - p.p));
    const Eigen::VectorXd q = state.q.segment(joint->first_variable(), n);
    Eigen::MatrixXd A(6, n);
    for (int k = 0; k < n; ++k) {
      Vec3 w, v;
      RelativeVelocity(joint->kinematics(), q, Eigen::VectorXd::Unit(n, k), &w, &v);
      A.col(k) << w, v;
    }
    qdot.segment(joint->first_variable(), n) = A.colPivHouseholderQr().solve(twist);
  }
  return qdot;
}

}  // namespace flexmbd
