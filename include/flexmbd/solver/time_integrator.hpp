#pragma once
/// @file
/// What every time-stepping scheme offers the simulation loop: attempt one step, report its outcome.

#include <memory>

#include "flexmbd/effects/modal_effect.hpp"
#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/state.hpp"
#include "flexmbd/solver/newton.hpp"

namespace flexmbd {

class Model;
class SparseSystem;

/// Outcome of one attempted step.
enum class StepStatus { kAccepted, kRejectedError, kRejectedEvent, kNewtonDiverged, kSingularMatrix };
const char* StepStatusName(StepStatus status);

struct StepResult {
  StepStatus status = StepStatus::kAccepted;
  double error = 0;  ///< local error estimate relative to the target (accept if <= 1)
  NewtonReport newton;
  StepLimit limit;  ///< what the effects with modes ask of this step (kRejectedEvent: limit.retry) and the next
};

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;

  /// Attempts a step of size h from `start`. On kAccepted `end` holds the converged end state.
  virtual StepResult Step(const State& start, double h, State* end) = 0;

  /// The context of the last converged step (for outputs such as joint efforts).
  virtual const StepContext& last_context() const = 0;
};

/// The scheme the model's solver settings name.
std::unique_ptr<TimeIntegrator> MakeTimeIntegrator(const Model& model, SparseSystem* system);

/// Local error estimate of the step that led to `end` (docs/theory.md, (T12)), relative to error_tol; h_before
/// is the size of the step before it. Zero until two steps have been taken.
double LocalErrorEstimate(const State& end, double h_before, double error_tol);

/// Round-off floor of Newton increments for a start state (its coordinates and joint variables).
double NoiseFloor(const Model& model, const State& start);

}  // namespace flexmbd
