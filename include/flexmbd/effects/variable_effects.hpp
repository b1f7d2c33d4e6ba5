#pragma once
/// @file
/// Effects on one relative-motion variable q of a joint, each an element of its own (docs/theory.md, (T10)):
///   spring  Q = -k (q_m - rest + alpha (dq - dq_lagged)), q_m the mid-step value: the exact discrete gradient
///           of k (q - rest)^2 / 2 plus the energy-decaying scheme's dissipation k alpha (dq - dq_lagged) dq >= 0
///   damper  Q = -c (q_f - q_i)/h: dissipates c dq^2/h >= 0 per step
///   drive   q_f = f(t_f), enforced by a multiplier lambda; the drive force on q is -lambda. Under a commanded
///           set-point s (State::commands) it follows s with a first-order lag instead (docs/theory.md, "Commands")
///   effort  Q = u, the commanded effort of State::commands held over the step: its work u dq is external
///   hold    q = q(0) in a static analysis, enforced by a multiplier lambda; in time steps lambda = 0: a body
///           released from rest in its static deflected shape (docs/config.md, `initial.static_hold`)

#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

class VariableSpring : public Element {
 public:
  VariableSpring(int variable, int variable_unknown, double stiffness, double rest);
  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddEnergy(const State& state, const Vec3& gravity, EnergyTally* tally) const override;
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

 private:
  int variable_;
  double stiffness_, rest_;
};

class VariableDamper : public Element {
 public:
  VariableDamper(int variable, int variable_unknown, double coefficient);
  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  bool HasRateParts(AnalysisMode mode) const override;
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                    Eigen::Ref<Eigen::MatrixXd> M) const override;
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

 private:
  int variable_;
  double coefficient_;
};

class VariableDrive : public Element {
 public:
  VariableDrive(int variable, int variable_unknown, int multiplier, int multiplier_unknown, TimeFunctionSpec law);
  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;
  const TimeFunctionSpec& law() const { return law_; }
  int variable() const { return variable_; }

 private:
  /// q_f the drive enforces: f(t_f), the lagged set-point, or q_i + h times the rate the context gives.
  double Target(const StepContext& ctx) const;

  int variable_, multiplier_;
  TimeFunctionSpec law_;
};

/// Holds the variable at its initial position in a static analysis only (`initial.static_hold`).
class VariableHold : public Element {
 public:
  VariableHold(int variable, int variable_unknown, int multiplier, int multiplier_unknown, double position);
  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;

 private:
  int variable_, multiplier_;
  double position_;  ///< the initial position held [rad or m]
};

/// The effort a controller commands on a variable; one on every variable, zero until commanded.
class VariableEffort : public Element {
 public:
  VariableEffort(int variable, int variable_unknown);
  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext&, Eigen::Ref<Eigen::MatrixXd>) const override {}
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

 private:
  int variable_;
};

}  // namespace flexmbd
