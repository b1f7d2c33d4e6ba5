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
}  // namespace

double ChooseStartingStep(TimeIntegrator* integrator, const State& start, double h, double dt_min,
                          StepController* controller) {
  while (h > dt_min) {
    State state = start, end;
    StepResult result;
    for (int k = 0; k < kStepsToAnEstimate; ++k) {
      result = integrator->Step(state, h, &end);
      controller->BookTrial(result);
      if (result.status != StepStatus::kAccepted) break;
      state = std::move(end);
    }
    switch (result.status) {
      case StepStatus::kAccepted: return h;  // three steps within the tolerance (or no estimate: no motion)
      case StepStatus::kRejectedEvent: return h;
      case StepStatus::kNewtonDiverged:
      case StepStatus::kSingularMatrix: h *= StepController::kFailureShrink; break;
      case StepStatus::kRejectedError:
        h *= std::max(kMaxShrinkPerRound, StepController::SizeFactor(result.error.error));
        break;
    }
  }
  return dt_min;
}

}  // namespace flexmbd
