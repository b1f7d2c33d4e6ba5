#pragma once
/// @file
/// Turns a start State and a trial vector of unknowns into the StepContext that elements read, and keeps the
/// elements' workspaces that its contexts carry.

#include <vector>

#include <Eigen/Core>

#include "flexmbd/elements/element.hpp"

namespace flexmbd {

class Model;

class StepContextBuilder {
 public:
  explicit StepContextBuilder(const Model& model);
  StepContextBuilder(const StepContextBuilder&) = delete;
  StepContextBuilder& operator=(const StepContextBuilder&) = delete;

  /// A dynamic step from `start` over h; `unknowns` holds (node increments, dq, lambda).
  const StepContext& Dynamic(const State& start, const Eigen::VectorXd& unknowns, double h,
                             const std::vector<NodeSchemeCoefficients>& coefficients);

  /// Static equilibrium at `iterate` moved by the increments in `unknowns` (lambda taken from there too),
  /// at time t with the given load factor.
  const StepContext& Static(const State& iterate, const Eigen::VectorXd& unknowns, double t, double load_factor);

  /// A step of size h ending at t_f whose equations hold at its end, at the end iterate `iterate` moved by the
  /// increments in `unknowns`. The caller fills the end velocities and accelerations (nodes(), variables()).
  StepContext& EndPoint(const State& iterate, const Eigen::VectorXd& unknowns, double t_f, double h);

  std::vector<NodeStep>& nodes() { return nodes_; }
  std::vector<VariableStep>& variables() { return variables_; }
  /// The element states of the last context; EndPoint leaves their rates at the iterate's stored rates, which
  /// the caller may overwrite.
  std::vector<ElementStateStep>& element_states() { return states_; }

  /// The state itself, as a static evaluation with no increment (for constraint checks and outputs).
  const StepContext& AtState(const State& state);

  const StepContext& context() const { return ctx_; }

  /// Dissipation coefficients of the energy-decaying scheme for the springs on each variable, used by the
  /// dynamic contexts built next (all zero unless set).
  void set_variable_dissipation(const std::vector<double>& alpha) { variable_alpha_ = alpha; }
  /// The energy-decaying coefficients of the elements' own stretch for the next Dynamic() (by Element::index()).
  void set_element_dissipation(const std::vector<double>& alpha) {
    element_alpha_ = alpha;
    ctx_.element_alpha = &element_alpha_;
  }

  /// Trial modes of the effects with modes for the dynamic contexts built next (null: the start state's).
  /// @pre the vector outlives the contexts built from it.
  void set_effect_modes(const std::vector<EffectState>* modes) { effect_modes_ = modes; }

  /// Whether the contexts built next ask for the geometric stiffness of constraint forces.
  void set_geometric_stiffness(bool on) { ctx_.geometric_stiffness = on; }

  /// The rates the drives follow in the contexts built next, instead of their laws or set-points (null: those).
  /// @pre the vector outlives the contexts built from it.
  void set_drive_rates(const Eigen::VectorXd* rates) { ctx_.drive_rates = rates; }

 private:
  void Fill(const State& start, const Eigen::VectorXd& unknowns, AnalysisMode mode);

  const Model& model_;
  std::vector<NodeStep> nodes_;
  std::vector<VariableStep> variables_;
  std::vector<ElementStateStep> states_;
  Eigen::VectorXd lambda_;
  std::vector<double> variable_alpha_;
  std::vector<double> element_alpha_;
  const std::vector<EffectState>* effect_modes_ = nullptr;
  ElementWorkspaces workspaces_;
  StepContext ctx_;
};

}  // namespace flexmbd
