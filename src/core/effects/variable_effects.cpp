#include "flexmbd/effects/variable_effects.hpp"

#include <cmath>

#include "flexmbd/math/time_function.hpp"

namespace flexmbd {

VariableSpring::VariableSpring(int variable, int variable_unknown, double stiffness, double rest)
    : variable_(variable), stiffness_(stiffness), rest_(rest) {
  unknowns_ = {variable_unknown};
}

void VariableSpring::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                 Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const VariableStep& q = (*ctx.variables)[variable_];
  const double force = stiffness_ * (0.5 * (q.q_i + q.q_f) - rest_ + q.alpha * (q.q_f - q.q_i - q.dq_lagged));
  r[0] += force;
  magnitude[0] += std::abs(force);
}

void VariableSpring::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  J(0, 0) += (ctx.mid_rate() + (*ctx.variables)[variable_].alpha) * stiffness_;
}

void VariableSpring::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const VariableStep& q = (*ctx.variables)[variable_];
  const double dq = q.q_f - q.q_i;
  work->numerical += stiffness_ * q.alpha * (dq - q.dq_lagged) * dq;
}

void VariableSpring::AddEnergy(const State& state, const Vec3&, EnergyTally* tally) const {
  const double stretch = state.q[variable_] - rest_;
  tally->potential += 0.5 * stiffness_ * stretch * stretch;
}

VariableDamper::VariableDamper(int variable, int variable_unknown, double coefficient)
    : variable_(variable), coefficient_(coefficient) {
  unknowns_ = {variable_unknown};
}

void VariableDamper::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                 Eigen::Ref<Eigen::VectorXd> magnitude) const {
  if (ctx.mode == AnalysisMode::kStatic) return;
  const VariableStep& q = (*ctx.variables)[variable_];
  const double rate = ctx.mode == AnalysisMode::kEndPoint ? q.qdot_f : (q.q_f - q.q_i) / ctx.h;
  const double force = coefficient_ * rate;
  r[0] += force;
  magnitude[0] += std::abs(force);
}

void VariableDamper::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  if (ctx.mode == AnalysisMode::kDynamic) J(0, 0) += coefficient_ / ctx.h;
}

bool VariableDamper::HasRateParts(AnalysisMode mode) const { return mode == AnalysisMode::kEndPoint; }

void VariableDamper::AddRateParts(const StepContext&, Eigen::Ref<Eigen::MatrixXd> D,
                                  Eigen::Ref<Eigen::MatrixXd>) const {
  D(0, 0) += coefficient_;
}

void VariableDamper::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const VariableStep& q = (*ctx.variables)[variable_];
  const double dq = q.q_f - q.q_i;
  work->dissipated += coefficient_ * dq * dq / ctx.h;
}

VariableDrive::VariableDrive(int variable, int variable_unknown, int multiplier, int multiplier_unknown,
                             TimeFunctionSpec law)
    : variable_(variable), multiplier_(multiplier), law_(std::move(law)) {
  unknowns_ = {variable_unknown, multiplier_unknown};
}

void VariableDrive::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const double lambda = (*ctx.lambda)[multiplier_];
  r[0] += lambda;
  magnitude[0] += std::abs(lambda);
  r[1] += (*ctx.variables)[variable_].q_f - Target(ctx);
}

double VariableDrive::Target(const StepContext& ctx) const {
  if (ctx.drive_rates != nullptr) return ctx.start->q[variable_] + ctx.h * (*ctx.drive_rates)[variable_];
  const VariableCommand& command = ctx.start->commands[variable_];
  if (!command.has_setpoint) return Evaluate(law_, ctx.t_f);
  if (ctx.mode == AnalysisMode::kStatic) return command.setpoint;
  // tau qdot + q = s solved exactly over the step, so that the path does not depend on the step sizes
  const double s = command.setpoint;
  return s + (ctx.start->q[variable_] - s) * std::exp(-ctx.h / command.time_constant);
}

void VariableDrive::AddTangent(const StepContext&, Eigen::Ref<Eigen::MatrixXd> J) const {
  J(0, 1) += 1.0;
  J(1, 0) += 1.0;
}

void VariableDrive::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const VariableStep& q = (*ctx.variables)[variable_];
  work->external -= (*ctx.lambda)[multiplier_] * (q.q_f - q.q_i);
}

VariableHold::VariableHold(int variable, int variable_unknown, int multiplier, int multiplier_unknown,
                           double position)
    : variable_(variable), multiplier_(multiplier), position_(position) {
  unknowns_ = {variable_unknown, multiplier_unknown};
}

// Only a static analysis holds; a time step keeps the row lambda = 0, so the pattern never changes and the hold
// does no work.
void VariableHold::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                               Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const double lambda = (*ctx.lambda)[multiplier_];
  if (ctx.mode != AnalysisMode::kStatic) {
    r[1] += lambda;
    return;
  }
  r[0] += lambda;
  magnitude[0] += std::abs(lambda);
  r[1] += (*ctx.variables)[variable_].q_f - position_;
}

void VariableHold::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  if (ctx.mode != AnalysisMode::kStatic) {
    J(1, 1) += 1.0;
    return;
  }
  J(0, 1) += 1.0;
  J(1, 0) += 1.0;
}

VariableEffort::VariableEffort(int variable, int variable_unknown) : variable_(variable) {
  unknowns_ = {variable_unknown};
}

void VariableEffort::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                 Eigen::Ref<Eigen::VectorXd> magnitude) const {
  // scaled with the applied loads in static load stepping
  const double effort = ctx.load_factor * ctx.start->commands[variable_].effort;
  r[0] -= effort;
  magnitude[0] += std::abs(effort);
}

void VariableEffort::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const VariableStep& q = (*ctx.variables)[variable_];
  work->external += ctx.start->commands[variable_].effort * (q.q_f - q.q_i);
}

}  // namespace flexmbd
