#include "flexmbd/elements/applied_load.hpp"

#include "flexmbd/math/rotation_vector_calculus.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {

AppliedLoad::AppliedLoad(int node, int first_unknown, const LoadSpec& spec, const Vec3& p_NP_N)
    : node_(node), spec_(spec), p_NP_N_(p_NP_N) {
  for (int k = 0; k < 6; ++k) unknowns_.push_back(first_unknown + k);
}

Vec6 AppliedLoad::GeneralisedForce(const StepContext& ctx, const NodeStep& n) const {
  const double t = ctx.force_time();
  const Vec3 value = ctx.load_factor * Evaluate(spec_.scale, t) * spec_.vector;
  const Mat3 R_mid = n.R_i * Exp(0.5 * n.theta);
  Vec6 q = Vec6::Zero();
  if (spec_.kind == LoadSpec::Kind::kMoment) {
    q.tail<3>() = spec_.frame == LoadSpec::Frame::kBody ? value : Vec3(R_mid.transpose() * value);
    return q;
  }
  const Vec3 F_W = spec_.frame == LoadSpec::Frame::kBody ? Vec3(R_mid * value) : value;
  q.head<3>() = F_W;
  q.tail<3>() = Skew(n.S * p_NP_N_) * (n.R_i.transpose() * F_W);
  return q;
}

void AppliedLoad::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                              Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const Vec6 q = GeneralisedForce(ctx, (*ctx.nodes)[node_]);
  r -= q;
  magnitude += q.cwiseAbs();
}

void AppliedLoad::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  // The load stiffness (a load that turns with the body, or acts at an offset) is O(h^2) against inertia in
  // dynamics: added there only when Newton asks for the full tangent, and always in statics. Exact derivative
  // of GeneralisedForce along theta (dx does not enter): the mid-step frame R_i Exp(theta/2) turns by
  // T(theta/2)/2 dtheta in a step, by dtheta at the end configuration, where R_i moves with it and S = I.
  if (ctx.mode != AnalysisMode::kStatic && !ctx.geometric_stiffness) return;
  const NodeStep& n = (*ctx.nodes)[node_];
  const double t = ctx.force_time();
  const Vec3 value = ctx.load_factor * Evaluate(spec_.scale, t) * spec_.vector;
  const RotationVectorCalculus half(0.5 * n.theta, RotationVectorCalculus::Level::kMaps);
  const Mat3 R_mid = n.R_i * half.exp();
  const Mat3 turn = ctx.at_end() ? Mat3::Identity() : Mat3(0.5 * half.tangent());  // d(frame) / d theta
  Mat3 dq_force = Mat3::Zero(), dq_moment = Mat3::Zero();
  if (spec_.kind == LoadSpec::Kind::kMoment) {
    if (spec_.frame == LoadSpec::Frame::kWorld) dq_moment = Skew(R_mid.transpose() * value) * turn;
  } else {
    const bool follower = spec_.frame == LoadSpec::Frame::kBody;
    const Vec3 F_W = follower ? Vec3(R_mid * value) : value;
    if (follower) dq_force = -R_mid * Skew(value) * turn;
    // Moment Skew(S p) R_i^T F_W of the force at the offset p.
    const Vec3 w = n.R_i.transpose() * F_W;
    Mat3 dw = n.R_i.transpose() * dq_force;
    if (ctx.at_end()) dw += Skew(w);
    dq_moment = Skew(n.S * p_NP_N_) * dw;
    if (!ctx.at_end()) {
      const RotationVectorCalculus c(n.theta, RotationVectorCalculus::Level::kFirst);
      Mat3 dSp;
      for (int l = 0; l < 3; ++l) dSp.col(l) = c.SecantDerivative(Vec3::Unit(l)) * p_NP_N_;
      dq_moment -= Skew(w) * dSp;
    }
  }
  J.block<3, 3>(0, 3) -= dq_force;
  J.block<3, 3>(3, 3) -= dq_moment;
}

void AppliedLoad::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const NodeStep& n = (*ctx.nodes)[node_];
  const Vec6 q = GeneralisedForce(ctx, n);
  work->external += q.head<3>().dot(n.dx) + q.tail<3>().dot(n.theta);
}

}  // namespace flexmbd
