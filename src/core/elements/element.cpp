#include "flexmbd/elements/element.hpp"

#include "flexmbd/common/error.hpp"

namespace flexmbd {

NodeStep MakeNodeStep(const NodeState& start, const Vec6& increment, AnalysisMode mode) {
  NodeStep n;
  const Vec3 dx = increment.head<3>();
  const Vec3 theta = increment.tail<3>();
  n.v_i = n.v_f = n.w_i = n.w_f = Vec3::Zero();
  if (mode != AnalysisMode::kDynamic) {
    n.x_i = n.x_f = start.x + dx;
    n.R_i = n.R_f = start.R * Exp(theta);
    n.dx = n.theta = Vec3::Zero();
    n.S = n.T = Mat3::Identity();
    return n;
  }
  n.x_i = start.x;
  n.x_f = start.x + dx;
  n.dx = dx;
  n.R_i = start.R;
  n.theta = theta;
  const IncrementMaps maps = IncrementMapsOf(theta);
  n.R_f = start.R * maps.exp;
  n.S = maps.secant;
  n.T = maps.right_jacobian;
  return n;
}

void SetNodeStepVelocities(const NodeState& start, double h, const NodeSchemeCoefficients& c, NodeStep* n) {
  n->v_i = start.v;
  n->w_i = start.w;
  // Scheme relation (theory eq. (T3)) solved for the end velocities.
  const double at = c.alpha_translation, ar = c.alpha_rotation;
  const double bt = 0.5 + at, br = 0.5 + ar;
  n->v_f = (n->dx / h - (0.5 - at) * n->v_i + at * h * start.a_prev) / bt;
  n->w_f = (n->theta / h - (0.5 - ar) * n->w_i + ar * h * start.alpha_prev) / br;
  n->dvf_ddx = 1.0 / (h * bt);
  n->dwf_dtheta = 1.0 / (h * br);
}

NodeStep PerturbNodeStep(const NodeStep& node, const Vec6& d, AnalysisMode mode) {
  NodeState start;
  Vec6 increment = d;
  if (mode != AnalysisMode::kDynamic) {
    start.x = node.x_f;
    start.R = node.R_f;
  } else {
    start.x = node.x_i;
    start.R = node.R_i;
    increment.head<3>() += node.dx;
    increment.tail<3>() += node.theta;
  }
  return MakeNodeStep(start, increment, mode);
}

void AddSchemeRateTerms(const Element& element, const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) {
  if (!element.HasRateParts(ctx.mode)) return;
  using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRatePartUnknowns, kMaxRatePartUnknowns>;
  const int n = element.num_local();
  FLEXMBD_DEMAND(n <= kMaxRatePartUnknowns);
  Block D = Block::Zero(n, n), M = Block::Zero(n, n);
  element.AddRateParts(ctx, D, M);
  const int node_unknowns = 6 * static_cast<int>(ctx.nodes->size());
  const int num_variables = ctx.variables != nullptr ? static_cast<int>(ctx.variables->size()) : 0;
  const int variable_unknowns = node_unknowns + num_variables;
  const int num_states = ctx.element_states != nullptr ? static_cast<int>(ctx.element_states->size()) : 0;
  const int state_unknowns = variable_unknowns + num_states;
  for (int j = 0; j < n; ++j) {
    const int u = element.unknowns()[j];
    double rate = 0.0, acceleration = 0.0;
    if (u < node_unknowns) {
      const NodeStep& s = (*ctx.nodes)[u / 6];
      rate = u % 6 < 3 ? s.dvf_ddx : s.dwf_dtheta;
      acceleration = s.dacc;
    } else if (u < variable_unknowns) {
      rate = (*ctx.variables)[u - node_unknowns].dqdotf_dq;
    } else if (u < state_unknowns) {
      rate = (*ctx.element_states)[u - variable_unknowns].drate;
    }
    if (rate != 0.0) J.col(j) += rate * D.col(j);
    if (acceleration != 0.0) J.col(j) += acceleration * M.col(j);
  }
}

void AddSchemeTangent(const Element& element, const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) {
  element.AddTangent(ctx, J);
  AddSchemeRateTerms(element, ctx, J);
}

}  // namespace flexmbd
