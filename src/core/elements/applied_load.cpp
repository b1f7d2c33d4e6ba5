#include "flexmbd/elements/applied_load.hpp"

#include "flexmbd/math/time_function.hpp"

namespace flexmbd {

AppliedLoad::AppliedLoad(int node, int first_unknown, const LoadSpec& spec, const Vec3& p_NP_N)
    : node_(node), spec_(spec), p_NP_N_(p_NP_N) {
  for (int k = 0; k < 6; ++k) unknowns_.push_back(first_unknown + k);
}

Vec6 AppliedLoad::GeneralisedForce(const StepContext& ctx, const NodeStep& n) const {
  const double t = ctx.at_end() ? ctx.t_f : 0.5 * (ctx.t_i + ctx.t_f);
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
  // dynamics: added there only when Newton asks for the full tangent, and always in statics. Forward
  // differences with a sqrt(eps) step.
  if (ctx.mode != AnalysisMode::kStatic && !ctx.geometric_stiffness) return;
  constexpr double kStep = 1.5e-8;
  const NodeStep& n = (*ctx.nodes)[node_];
  const Vec6 base = GeneralisedForce(ctx, n);
  for (int k = 0; k < 6; ++k) {
    const Vec6 d = kStep * Vec6::Unit(k);
    J.col(k) -= (GeneralisedForce(ctx, PerturbNodeStep(n, d, ctx.mode)) - base) / kStep;
  }
}

void AppliedLoad::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const NodeStep& n = (*ctx.nodes)[node_];
  const Vec6 q = GeneralisedForce(ctx, n);
  work->external += q.head<3>().dot(n.dx) + q.tail<3>().dot(n.theta);
}

}  // namespace flexmbd
