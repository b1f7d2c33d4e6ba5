#include "flexmbd/solver/time_integrator.hpp"

#include <algorithm>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/energy_decaying_integrator.hpp"
#include "flexmbd/solver/generalized_alpha_integrator.hpp"

namespace flexmbd {
namespace {
// Velocity scale below which the error estimate is not normalised further [m/s or rad/s].
constexpr double kVelocityFloor = 1.0e-6;
// Second-order local position error is h^3 |da/dt| / 12 (docs/theory.md, (T12)).
constexpr double kLocalErrorConstant = 1.0 / 12.0;
}  // namespace

const char* StepStatusName(StepStatus status) {
  switch (status) {
    case StepStatus::kAccepted: return "accepted";
    case StepStatus::kRejectedError: return "local error above tolerance";
    case StepStatus::kRejectedEvent: return "stop or friction event";
    case StepStatus::kNewtonDiverged: return "Newton did not converge";
    case StepStatus::kSingularMatrix: return "singular iteration matrix";
  }
  return "unknown";
}

std::unique_ptr<TimeIntegrator> MakeTimeIntegrator(const Model& model, SparseSystem* system) {
  if (model.solver().integrator == SolverSpec::Integrator::kGeneralizedAlpha) {
    return std::make_unique<GeneralizedAlphaIntegrator>(model, system);
  }
  return std::make_unique<EnergyDecayingIntegrator>(model, system);
}

double LocalErrorEstimate(const State& end, double h_before, double error_tol) {
  if (end.history_steps < 2) return 0.0;
  const double h = end.h_prev;
  const double v_scale = std::max(kVelocityFloor, end.peak_speed);
  const double w_scale = std::max(kVelocityFloor, end.peak_spin);
  // Local position error h^3 |da/dt| / 12 with da/dt ~ (a_n - a_{n-1}) / ((h + h_before)/2), relative to the
  // displacement h v_scale of a step at the run's peak speed (a slow phase is judged on the scale of the
  // whole motion, not of its own, vanishing, speed).
  const double weight = kLocalErrorConstant * 2.0 * h * h / (h + h_before);
  double error = 0;
  for (const NodeState& n : end.nodes) {
    error = std::max(error, weight * (n.a_prev - n.a_prev2).norm() / v_scale);
    error = std::max(error, weight * (n.alpha_prev - n.alpha_prev2).norm() / w_scale);
  }
  return error / error_tol;
}

double NoiseFloor(const Model& model, const State& start) {
  double magnitude = model.length_scale();
  if (start.q.size() > 0) magnitude = std::max(magnitude, start.q.cwiseAbs().maxCoeff());
  return RoundOffFloor(magnitude);
}

}  // namespace flexmbd
