#include "flexmbd/solver/step_controller.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace flexmbd {
namespace {
// Classical controller constants (Hairer, Norsett & Wanner, Solving ODEs I, sec. II.4): safety factor and
// the bounds on one change of step size.
constexpr double kSafety = 0.9;
constexpr double kMaxGrowth = 2.0;
constexpr double kMinShrink = 0.2;
// After a Newton failure or a singular matrix the step is cut by this factor.
constexpr double kFailureShrink = 0.25;
// The error estimate is O(h^2) (docs/theory.md, (T12)).
constexpr double kErrorOrder = 2.0;
}  // namespace

std::string StepStatistics::Summary() const {
  std::ostringstream out;
  out << "steps: " << accepted << " accepted, " << rejected() << " rejected (" << rejected_error << " local error, " << rejected_event << " stop or friction event, "
      << rejected_newton << " Newton not converged, " << rejected_singular << " singular matrix); "
      << newton_iterations << " Newton iterations; step size " << h_min << " to " << h_max << " s";
  return out.str();
}

StepController::StepController(const SolverSpec& solver) : solver_(solver) {}

double StepController::Next(double h, const StepResult& result) {
  stats_.newton_iterations += result.newton.iterations;
  switch (result.status) {
    case StepStatus::kAccepted:
      stats_.h_min = stats_.accepted == 0 ? h : std::min(stats_.h_min, h);
      stats_.h_max = std::max(stats_.h_max, h);
      ++stats_.accepted;
      break;
    case StepStatus::kRejectedError: ++stats_.rejected_error; break;
    case StepStatus::kRejectedEvent: ++stats_.rejected_event; return result.limit.retry;
    case StepStatus::kNewtonDiverged: ++stats_.rejected_newton; break;
    case StepStatus::kSingularMatrix: ++stats_.rejected_singular; break;
  }
  if (result.status == StepStatus::kNewtonDiverged || result.status == StepStatus::kSingularMatrix) {
    return h * kFailureShrink;
  }
  if (!solver_.adaptive) return std::min(result.status == StepStatus::kAccepted ? solver_.dt : h, result.limit.next);
  const double factor = result.error > 0 ? kSafety * std::pow(result.error, -1.0 / kErrorOrder) : kMaxGrowth;
  return std::min({solver_.dt_max, h * std::clamp(factor, kMinShrink, kMaxGrowth), result.limit.next});
}

}  // namespace flexmbd
