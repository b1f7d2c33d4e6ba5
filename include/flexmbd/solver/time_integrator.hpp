#pragma once
/// @file
/// What every time-stepping scheme offers the simulation loop: attempt one step, report its outcome.

#include <array>
#include <memory>

#include "flexmbd/effects/modal_effect.hpp"
#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/state.hpp"
#include "flexmbd/solver/newton.hpp"

namespace flexmbd {

class Model;
class SparseSystem;
struct SolverSpec;

/// Outcome of one attempted step.
enum class StepStatus { kAccepted, kRejectedError, kRejectedEvent, kNewtonDiverged, kSingularMatrix };
const char* StepStatusName(StepStatus status);

/// Local error estimate of a step (docs/theory.md, (T12)).
struct ErrorEstimate {
  /// Weighted RMS of the local errors relative to their tolerances (accept if <= 1); NaN while the step has no
  /// estimate (fewer than two steps of acceleration history, e.g. at the start or after an impact).
  double error = 0;
  int worst_unknown = -1;  ///< first unknown of the node translation, rotation or joint variable that weighs most
};

struct StepResult {
  StepStatus status = StepStatus::kAccepted;
  ErrorEstimate error;
  NewtonReport newton;
  StepLimit limit;  ///< what the effects with modes ask of this step (kRejectedEvent: limit.retry) and the next
};

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;

  /// Attempts a step of size h from `start`. On kAccepted `end` holds the converged end state.
  virtual StepResult Step(const State& start, double h, State* end) = 0;

  /// A step of the trials that choose a run's first step (docs/theory.md, "First step"): Step without the scheme's
  /// numerical dissipation, which would damp a motion too fast for h and hide it from the error estimate (T12).
  virtual StepResult TrialStep(const State& start, double h, State* end) { return Step(start, h, end); }

  /// The context of the last converged step (for outputs such as joint efforts).
  virtual const StepContext& last_context() const = 0;

  /// The start of the last step attempted where it was not the given state but that state with its velocities
  /// projected (a drive's rate jump, a redone friction event: docs/theory.md); null where it was the given state.
  virtual const State* last_projected_start() const { return nullptr; }
};

/// The scheme the model's solver settings name.
std::unique_ptr<TimeIntegrator> MakeTimeIntegrator(const Model& model, SparseSystem* system);

/// The absolute floor of the local error test on joint variables [rad or m] (solver.error_floor.joint, or its
/// default).
double JointErrorFloor(const SolverSpec& solver);

/// What the local error test (T12) accepts in a joint variable over a step of size h [rad or m]: its floor plus
/// error_tol times the step's travel at the variable's own peak rate so far, `peak_rate`.
double JointErrorScale(const SolverSpec& solver, double h, double peak_rate);

/// The derivative of a motion from the mean rates of two consecutive steps of sizes h_newer and h_older (the rates
/// at the step midpoints): their divided difference over the span between the midpoints.
template <typename Rate>
Rate MeanRateDerivative(const Rate& newer, const Rate& older, double h_newer, double h_older) {
  return (newer - older) / (0.5 * (h_newer + h_older));
}

/// The third derivative of a motion from the mean rates of three consecutive steps of sizes h, newest first (the rates
/// at the step midpoints to O(h^2)): their second divided difference over the three midpoints (docs/theory.md, (T12)).
template <typename Rate>
Rate MeanRateThirdDerivative(const Rate& newest, const Rate& middle, const Rate& oldest,
                              const std::array<double, 3>& h) {
  const double span_newer = 0.5 * (h[0] + h[1]), span_older = 0.5 * (h[1] + h[2]);
  return ((newest - middle) / span_newer - (middle - oldest) / span_older) / (0.5 * (span_newer + span_older));
}

/// The alternating error at the end of the newest of three steps (sizes h, newest first) of a motion whose ends carry
/// +-x in turn: a motion with a constant second derivative over the steps, so shifted, has the mean rates `newest`,
/// `middle`, `oldest` = its rates at the midpoints plus 2x/h_0, -2x/h_1, 2x/h_2; solved for x (docs/theory.md,
/// "Algebraic rotations"). On a smooth motion it is of the order of the local error (T12).
double AlternatingOffset(double newest, double middle, double oldest, const std::array<double, 3>& h);

/// The largest step that begins with a jump of `acceleration_jump` in a joint variable's acceleration [rad/s^2 or
/// m/s^2] and has no error history (docs/theory.md, (F3'')): where the estimate (T12), run across the jump with equal
/// steps, would find the error acceptable, |jump| h^2 / 24 = floor + error_tol h peak_rate (the variable's own peak
/// rate so far). Infinity with fixed steps or without a jump.
double StepAfterJump(const SolverSpec& solver, double acceleration_jump, double peak_rate);

/// Local error estimate of the step that led to `end` (docs/theory.md, (T12); damped beams (T12b), (T12c)), from its
/// mean-rate history.
ErrorEstimate EstimateLocalError(const Model& model, const State& end);

/// Books an accepted step of size `h` from `start` into the end state's error-test history: its size and count
/// (h_prev, history_steps), its mean rates, and the peak speeds that scale the test. Called by every scheme once
/// `end` holds its positions and rates.
void RecordStepHistory(const State& start, double h, State* end);

/// Round-off floor of Newton increments for a start state (its node coordinates and joint variables).
double NoiseFloor(const Model& model, const State& start);

/// The kinematic unknowns of a step that coasts at the start velocities: h v, h w, h qdot.
Eigen::VectorXd CoastingIncrements(const Model& model, const State& start, double h);

}  // namespace flexmbd
