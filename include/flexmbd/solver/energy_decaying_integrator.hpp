#pragma once
/// @file
/// The energy-decaying time step (docs/theory.md, section "Time integration", eqs. (T3)-(T6)). For each node
///   x_f - x_i = h [(v_i + v_f)/2 + a (v_f - v_i - h a_prev)],   and the same for theta and w,
/// where a_prev is the previous step's mean acceleration, so the added term is O(h^3) on smooth motion and the
/// scheme stays second order. Forces use exact discrete gradients and constraints hold at the end of the step,
/// so for a conservative system
///   E_f - E_i = - a m (v_f - v_i - h a_prev) . (v_f - v_i) - (same for rotation with J).
/// a is alpha_inf where that product is >= 0 and 0 where it is not (the step is redone with a = 0 for a node
/// whose product turns out negative), so the energy never increases. Springs on joint variables dissipate the
/// same way on their stretch, k a (dq - dq_lagged) dq >= 0, which damps the potential part of unresolved modes.
/// alpha_inf = 0 is energy preserving.

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "flexmbd/solver/dissipation_judging.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/sticking_redundancy.hpp"
#include "flexmbd/solver/tangent_reuse.hpp"
#include "flexmbd/solver/time_integrator.hpp"
#include "flexmbd/solver/velocity_projection.hpp"

namespace flexmbd {

/// alpha_inf of the scheme from the high-frequency velocity amplification rho_inf in [kMinRhoInf, 1].
constexpr double kMinRhoInf = 1.0 / 3.0;
double DissipationFromRhoInf(double rho_inf);

class EnergyDecayingIntegrator : public TimeIntegrator {
 public:
  EnergyDecayingIntegrator(const Model& model, SparseSystem* system);

  StepResult Step(const State& start, double h, State* end) override;
  StepResult TrialStep(const State& start, double h, State* end) override;
  const StepContext& last_context() const override { return builder_.context(); }
  const State* last_projected_start() const override { return started_projected_ ? &projected_start_ : nullptr; }

 private:
  // The dissipation coefficient of each node (kinetic part) and of each joint variable (its springs).
  struct Coefficients {
    std::vector<NodeSchemeCoefficients> nodes;
    std::vector<double> variables;
    std::vector<double> elements;  ///< by Element::index(): elements that dissipate on their own stretch
    bool any() const;              ///< some coefficient is nonzero
  };
  // Chosen before the step from the previous steps' accelerations and the last step's element checks; all zero in a
  // step without dissipation (the energy-preserving relation).
  Coefficients Choose(const State& start, bool dissipation) const;
  // Turns off the dissipation of nodes, variables and elements whose converged step would gain energy; true if
  // any was.
  bool DropEnergyGainingDissipation(const State& start, double h, Coefficients* c) const;
  // Records, at the converged step whose context the builder holds with coefficients `c`, which elements' own
  // stretch dissipates with the scheme's term, whether or not the term was on.
  void RecordElementDissipation(const Coefficients& c);
  Eigen::VectorXd Predict(const State& start, double h) const;
  // A step from `given`, with the scheme's dissipation or without it (Step, TrialStep).
  StepResult StepFrom(const State& given, double h, State* end, bool dissipation);
  // The step from `start` (StepFrom's work, from the start StartOf chose).
  StepResult SolveStep(const State& start, double h, State* end, bool dissipation);
  // The state a step of size h starts from: `given`; where a drive's rate jumps at `given`, `given` with its
  // velocities carried across the jump; or, once a step from it much shorter than the one before was redone for a
  // friction event, `given` with its velocities projected onto the constraints (both kept in projected_start_).
  const State& StartOf(const State& given, double h);
  // Asks every effect with modes whether the converged step contradicts its trial mode; true if any did.
  bool ReviseModes();
  // The effects' step-size requests and their state at the end of the accepted step; true when a friction asked to
  // redo the step (a slip reversal located from end rates).
  bool CommitEffects(State* end, StepLimit* limit) const;
  // True when an effect changed its mode from `start` to `end` with a jump in the motion (ModeChangesAreSmooth).
  bool ModesJumped(const State& start, const State& end) const;
  /// theta / (1 - theta) a judging solve assumes for its first increment (NaN while no rate was measured).
  double ExpectedJudgingContraction() const;
  void Commit(const State& start, const Eigen::VectorXd& unknowns, double h,
              const std::vector<NodeSchemeCoefficients>& coefficients, State* end);

  const Model& model_;
  SparseSystem* system_;
  StepContextBuilder builder_;
  VelocityProjection projection_;  ///< applied after steps whose modes jumped or whose contacts came to rest
  StickingRedundancy redundancy_;  ///< leaves out sticking rows that repeat other constraints, per trial modes
  double alpha_inf_;
  std::vector<bool> held_;          ///< per effect slot: held in the projection (a contact brought to rest)
  std::vector<Mat3> node_inertia_;  ///< rotational inertia of each node's body, weights the dissipation check
  std::vector<EffectState> modes_;  ///< trial modes of the step being solved
  bool end_rate_event_ = false;  ///< the last step solved was redone for a friction event (CommitEffects)
  /// Time of the start from which a step much shorter than the one before was redone for a friction event (StartOf).
  double short_event_start_ = std::numeric_limits<double>::quiet_NaN();
  State projected_start_;  ///< a start with its velocities projected (StartOf)
  bool started_projected_ = false;  ///< the last step attempted started from projected_start_
  TangentReuse tangent_reuse_;     ///< whether a step starts from the previous one's factorisation, learnt
  DissipationJudging judging_;      ///< when a step judges its dissipation terms, learnt from the steps taken
  std::vector<double> elements_all_on_;  ///< by Element::index(): alpha_inf for elements with a stretch of their own
  /// By Element::index(): whether the element's own stretch would have dissipated with the scheme's term over the
  /// last converged step (true before any); a step starts the term on only there (Choose).
  std::vector<bool> elements_dissipated_;
  /// theta / (1 - theta) of the last judging solve, or its expectation aged by one solve (NaN: none yet)
  double judging_contraction_factor_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace flexmbd
