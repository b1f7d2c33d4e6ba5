#include "flexmbd/solver/step_context_builder.hpp"

#include "flexmbd/model/model.hpp"

namespace flexmbd {

StepContextBuilder::StepContextBuilder(const Model& model) : model_(model), workspaces_(model.elements()) {
  nodes_.resize(model.num_nodes());
  variables_.resize(model.num_variables());
  states_.resize(model.num_element_states());
  ctx_.nodes = &nodes_;
  ctx_.element_states = &states_;
  ctx_.variables = &variables_;
  ctx_.lambda = &lambda_;
  ctx_.workspaces = &workspaces_;
  ctx_.gravity = model.solver().gravity;
}

void StepContextBuilder::Fill(const State& start, const Eigen::VectorXd& unknowns, AnalysisMode mode) {
  ctx_.mode = mode;
  ctx_.start = &start;
  ctx_.effects = &start.effects;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    nodes_[k] = MakeNodeStep(start.nodes[k], unknowns.segment<6>(model_.node_unknown(k)), mode);
  }
  for (int k = 0; k < model_.num_variables(); ++k) {
    VariableStep& v = variables_[k];
    v.q_f = start.q[k] + unknowns[model_.variable_unknown(k)];
    v.q_i = mode == AnalysisMode::kDynamic ? start.q[k] : v.q_f;
    v.qdot_i = start.qdot[k];
    v.alpha = v.dq_lagged = 0.0;
  }
  // Element states at the end configuration (S3); a dynamic step moves them to the midpoint (S2).
  for (int k = 0; k < model_.num_element_states(); ++k) {
    ElementStateStep& x = states_[k];
    x.x_f = start.element_states[k] + unknowns[model_.element_state_unknown(k)];
    x.x_i = mode == AnalysisMode::kDynamic ? start.element_states[k] : x.x_f;
    x.value = x.x_f;
    x.rate = mode == AnalysisMode::kEndPoint ? start.element_state_rates[k] : 0.0;
    x.drate = 0.0;
  }
  lambda_ = unknowns.tail(model_.num_multipliers());
}

const StepContext& StepContextBuilder::Dynamic(const State& start, const Eigen::VectorXd& unknowns, double h,
                                               const std::vector<NodeSchemeCoefficients>& coefficients) {
  Fill(start, unknowns, AnalysisMode::kDynamic);
  if (effect_modes_ != nullptr) ctx_.effects = effect_modes_;
  for (int k = 0; k < model_.num_nodes(); ++k) SetNodeStepVelocities(start.nodes[k], h, coefficients[k], &nodes_[k]);
  const bool has_history = start.dq_prev.size() == model_.num_variables() && start.h_prev > 0;
  for (int k = 0; k < model_.num_variables(); ++k) {
    variables_[k].alpha = k < static_cast<int>(variable_alpha_.size()) ? variable_alpha_[k] : 0.0;
    variables_[k].dq_lagged = has_history ? h / start.h_prev * start.dq_prev[k] : 0.0;
  }
  for (ElementStateStep& x : states_) {
    x.value = 0.5 * (x.x_i + x.x_f);
    x.rate = (x.x_f - x.x_i) / h;
    x.drate = 1.0 / h;
  }
  ctx_.t_i = start.t;
  ctx_.t_f = start.t + h;
  ctx_.h = h;
  ctx_.load_factor = 1.0;
  return ctx_;
}

const StepContext& StepContextBuilder::Static(const State& iterate, const Eigen::VectorXd& unknowns, double t,
                                              double load_factor) {
  Fill(iterate, unknowns, AnalysisMode::kStatic);
  ctx_.t_i = ctx_.t_f = t;
  ctx_.h = 1.0;
  ctx_.load_factor = load_factor;
  return ctx_;
}

StepContext& StepContextBuilder::EndPoint(const State& iterate, const Eigen::VectorXd& unknowns, double t_f,
                                          double h) {
  Fill(iterate, unknowns, AnalysisMode::kEndPoint);
  ctx_.t_i = t_f - h;
  ctx_.t_f = t_f;
  ctx_.h = h;
  ctx_.load_factor = 1.0;
  return ctx_;
}

const StepContext& StepContextBuilder::AtState(const State& state) {
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model_.num_unknowns());
  unknowns.tail(model_.num_multipliers()) = state.lambda;
  return Static(state, unknowns, state.t, 1.0);
}

}  // namespace flexmbd
