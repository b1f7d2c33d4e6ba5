#include "flexmbd/solver/starting_step.hpp"

#include <algorithm>
#include <cmath>

namespace flexmbd {
namespace {
// The estimate needs the mean rates of three steps (docs/theory.md, (T12)).
constexpr int kStepsToAnEstimate = 3;
// One round may shrink the step by at most this factor: an estimate from steps far too large for the motion is
// only a rough guide, and the next round measures again.
constexpr double kMaxShrinkPerRound = 0.01;
// Events one round resolves before it gives up on an estimate: a model that changes mode at every step (chattering
// contact) has none to give, and the run then starts at the size tried, resolving its events itself.
constexpr int kMaxEventsPerRound = 16;
}  // namespace

double ChooseStartingStep(TimeIntegrator* integrator, const State& start, double h, double dt_min,
                          StepController* controller) {
  while (h > dt_min) {
    State state = start, end;
    StepResult result;
    double size = h;  // of the step tried: h, or less where an event or an effect's limit asks for it
    int steps_since_event = 0, events = 0;
    while (steps_since_event < kStepsToAnEstimate) {
      // Without the scheme's dissipation, which damps a motion too fast for the step and hid it from the estimate
      // (a contact touched at rest under a preload, two steps per period of its oscillation: docs/theory.md,
      // "First step").
      result = integrator->TrialStep(state, size, &end);
      controller->BookTrial(result);
      if (result.status == StepStatus::kRejectedEvent) {
        // Resolved as the run resolves it: the step redone at the event. The jump it makes starts the estimate
        // again, so the steps of size h after it are the ones measured (docs/theory.md, "First step").
        if (++events > kMaxEventsPerRound || result.limit.retry < dt_min) return h;
        size = result.limit.retry;
        steps_since_event = 0;
        continue;
      }
      if (result.status != StepStatus::kAccepted) break;
      state = std::move(end);
      ++steps_since_event;
      if (steps_since_event < kStepsToAnEstimate) size = std::min(h, result.limit.next);
    }
    switch (result.status) {
      case StepStatus::kAccepted: return h;  // three steps within the tolerance (or no estimate: no motion)
      case StepStatus::kRejectedEvent: return h;  // not reached: events are resolved above
      case StepStatus::kNewtonDiverged:
      case StepStatus::kSingularMatrix: h = size * StepController::kFailureShrink; break;
      case StepStatus::kRejectedError:
        h = size * std::max(kMaxShrinkPerRound, StepController::SizeFactor(result.error.error));
        break;
    }
  }
  return dt_min;
}

}  // namespace flexmbd
