#include "flexmbd/solver/step_controller.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace {
// Classical controller constants (Hairer, Norsett & Wanner, Solving ODEs I, sec. II.4): safety factor and
// the bounds on one change of step size.
constexpr double kSafety = 0.9;
constexpr double kMaxGrowth = 2.0;
constexpr double kMinShrink = 0.2;
// The error estimate is O(h^2) (docs/theory.md, (T12)).
constexpr double kErrorOrder = 2.0;
// Proportional-integral control of an accepted step that follows another estimated one (Gustafsson; Hairer & Wanner,
// Solving ODEs II, sec. IV.2): h err_n^(-0.3) err_{n-1}^(0.1) instead of h err_n^(-1/2) damps the swings of a
// noisy estimate. Chosen on the work-precision cases (bench/README.md): rejections of the beam arm fell from 28%
// to 2-5% of its steps, and the five cases' steps at equal error changed by -10 ... +15% counting rejections.
constexpr double kPiCurrent = 0.3;
constexpr double kPiPrevious = 0.1;
// An entry of the error norm: a node's translation or rotation as a whole, or a joint variable.
std::string DescribeErrorEntry(const Model& model, int unknown) {
  if (unknown >= model.node_unknown(model.num_nodes())) return model.DescribeUnknown(unknown);
  const int node = unknown / 6;
  return model.node_name(node) + (unknown - model.node_unknown(node) < 3 ? " translation" : " rotation");
}
}  // namespace

std::string StepStatistics::Summary(const Model& model) const {
  std::ostringstream out;
  out << "steps: " << accepted << " accepted, " << rejected() << " rejected (" << rejected_error << " local error, "
      << rejected_event << " stop or friction event, " << rejected_newton << " Newton not converged, "
      << rejected_singular << " singular matrix); " << newton_iterations << " Newton iterations (" << tangents
      << " with a fresh tangent); step size " << h_min << " to " << h_max << " s";
  if (trial > 0) out << "; " << trial << " trial steps chose the first step " << h_start << " s";
  const auto most = std::max_element(limited_by.begin(), limited_by.end(),
                                     [](const auto& a, const auto& b) { return a.second < b.second; });
  if (most != limited_by.end()) {
    out << "; local error limited the step most at " << DescribeErrorEntry(model, most->first) << " (" << most->second
        << " times)";
  }
  return out.str();
}

double StepController::SizeFactor(double error) { return kSafety * std::pow(error, -1.0 / kErrorOrder); }

double StepController::BoundedSizeFactor(double error) { return std::clamp(SizeFactor(error), kMinShrink, kMaxGrowth); }

StepController::StepController(const SolverSpec& solver) : solver_(solver), estimated_next_(solver.dt) {}

void StepController::BookTrial(const StepResult& result) {
  ++stats_.trial;
  stats_.newton_iterations += result.newton.iterations;
  stats_.tangents += result.newton.tangents;
}

void StepController::Start(double h) {
  stats_.h_start = h;
  estimated_next_ = h;
}

void StepController::Restart(double h) {
  estimated_next_ = std::min(estimated_next_, h);
  previous_error_ = 0;
}

double StepController::Next(double h, const StepResult& result) {
  stats_.newton_iterations += result.newton.iterations;
  stats_.tangents += result.newton.tangents;
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
  const double error = result.error.error;
  double next = 0;
  if (!std::isnan(error)) {  // NaN: no estimate; an infinite error (tolerances underflowing) shrinks most
    const bool accepted = result.status == StepStatus::kAccepted;
    double factor = error > 0 ? SizeFactor(error) : kMaxGrowth;
    if (accepted && error > 0 && previous_error_ > 0) {
      factor = kSafety * std::pow(error, -kPiCurrent) * std::pow(previous_error_, kPiPrevious);
    }
    const double max_growth = accepted && !rejected_last_ ? kMaxGrowth : 1.0;
    next = h * std::clamp(factor, kMinShrink, max_growth);
    rejected_last_ = !accepted;
    if (accepted) {
      estimated_next_ = next;
      previous_error_ = error;
    }
    if (result.error.worst_unknown >= 0 && factor < 1.0) ++stats_.limited_by[result.error.worst_unknown];
  } else {
    // Without an estimate (the first steps; after an impact or a stick-slip transition, whose jump says nothing
    // about the steps after it) the step may grow back to what the last estimate allowed, never beyond.
    next = std::min(h * kMaxGrowth, std::max(h, estimated_next_));
    previous_error_ = 0;
  }
  return std::min({solver_.dt_max, next, result.limit.next});
}

}  // namespace flexmbd
