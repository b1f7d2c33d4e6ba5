#include "flexmbd/elements/rigid_body.hpp"

namespace flexmbd {

RigidBody::RigidBody(int node, int first_unknown, double mass, const Mat3& inertia_cm)
    : node_(node), mass_(mass), inertia_(inertia_cm) {
  for (int k = 0; k < 6; ++k) unknowns_.push_back(first_unknown + k);
}

void RigidBody::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                            Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const NodeStep& n = (*ctx.nodes)[node_];
  const Vec3 weight = ctx.load_factor * mass_ * ctx.gravity;
  r.head<3>() -= weight;
  magnitude.head<3>() += weight.cwiseAbs();
  if (ctx.mode == AnalysisMode::kStatic) return;
  if (ctx.mode == AnalysisMode::kEndPoint) {
    // Newton-Euler at the end of the step, rotation rows in the node frame there.
    const Vec3 translational = mass_ * n.vdot_f;
    const Vec3 rotational = inertia_ * n.wdot_f + n.w_f.cross(inertia_ * n.w_f);
    r.head<3>() += translational;
    r.tail<3>() += rotational;
    // The accelerations come from differences of increments and velocities of size h |v|: their round-off
    // scales with the momenta over h, as in the mid-step form.
    magnitude.head<3>() += translational.cwiseAbs() + mass_ * (n.v_f.cwiseAbs() + n.v_i.cwiseAbs()) / ctx.h;
    magnitude.tail<3>() += (inertia_ * n.wdot_f).cwiseAbs() + n.w_f.cross(inertia_ * n.w_f).cwiseAbs() +
                           ((inertia_ * n.w_f).cwiseAbs() + (inertia_ * n.w_i).cwiseAbs()) / ctx.h;
    return;
  }
  const Mat3 E = Exp(n.theta);
  r.head<3>() += mass_ * (n.v_f - n.v_i) / ctx.h;
  r.tail<3>() += (E * (inertia_ * n.w_f) - inertia_ * n.w_i) / ctx.h;
  // The momenta whose difference makes the inertia term: their size sets the round-off of the residual.
  magnitude.head<3>() += mass_ * (n.v_f.cwiseAbs() + n.v_i.cwiseAbs()) / ctx.h;
  magnitude.tail<3>() += ((E * inertia_ * n.w_f).cwiseAbs() + (inertia_ * n.w_i).cwiseAbs()) / ctx.h;
}

void RigidBody::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  if (ctx.mode != AnalysisMode::kDynamic) return;
  // d/dtheta [Exp(theta) J w_f] at held w_f = -Exp(theta) Skew(J w_f) T(theta).
  const NodeStep& n = (*ctx.nodes)[node_];
  J.bottomRightCorner<3, 3>() -= Exp(n.theta) * Skew(inertia_ * n.w_f) * n.T / ctx.h;
}

bool RigidBody::HasRateParts(AnalysisMode mode) const { return mode != AnalysisMode::kStatic; }

void RigidBody::AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                             Eigen::Ref<Eigen::MatrixXd> M) const {
  const NodeStep& n = (*ctx.nodes)[node_];
  if (ctx.mode == AnalysisMode::kEndPoint) {
    M.topLeftCorner<3, 3>().diagonal().array() += mass_;
    M.bottomRightCorner<3, 3>() += inertia_;
    D.bottomRightCorner<3, 3>() += Skew(n.w_f) * inertia_ - Skew(inertia_ * n.w_f);
    return;
  }
  D.topLeftCorner<3, 3>().diagonal().array() += mass_ / ctx.h;
  D.bottomRightCorner<3, 3>() += Exp(n.theta) * inertia_ / ctx.h;
}

void RigidBody::AddEnergy(const State& state, const Vec3& gravity, EnergyTally* tally) const {
  const NodeState& n = state.nodes[node_];
  tally->kinetic += 0.5 * mass_ * n.v.squaredNorm() + 0.5 * n.w.dot(inertia_ * n.w);
  tally->potential -= mass_ * gravity.dot(n.x);
}

}  // namespace flexmbd
