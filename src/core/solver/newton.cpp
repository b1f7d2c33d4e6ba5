#include "flexmbd/solver/newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/sparse_system.hpp"

namespace flexmbd {
namespace {
// Force magnitudes below this are treated as this [N]: keeps the relative test meaningful at rest.
constexpr double kForceFloor = 1.0e-9;
// Kinematic increments are compared to tol times this floor [m or rad] when the motion itself is tiny.
constexpr double kIncrementFloor = 1.0e-6;


struct ResidualCheck {
  double force = 0, constraint = 0;
  int worst = -1;
};

ResidualCheck CheckResidual(const Model& model, const SparseSystem& system) {
  const Eigen::VectorXd& r = system.residual();
  const Eigen::VectorXd& m = system.magnitude();
  const int n_force = model.num_unknowns() - model.num_multipliers();
  const double scale = std::max(m.head(n_force).cwiseAbs().maxCoeff(), kForceFloor);
  ResidualCheck check;
  double worst_scaled = -1;
  for (int k = 0; k < r.size(); ++k) {
    const bool force = k < n_force;
    const double scaled = force ? std::abs(r[k]) / scale : std::abs(r[k]) / kConstraintTolerance;
    if (force) check.force = std::max(check.force, std::abs(r[k]) / scale);
    else check.constraint = std::max(check.constraint, std::abs(r[k]));
    if (scaled > worst_scaled) {
      worst_scaled = scaled;
      check.worst = k;
    }
  }
  return check;
}
}  // namespace

double RoundOffFloor(double magnitude) {
  // A hundred units in the last place: the noise of a few dozen operations on such coordinates.
  constexpr double kRoundOffUnits = 100.0;
  return kRoundOffUnits * std::numeric_limits<double>::epsilon() * std::max(1.0, magnitude);
}

NewtonReport SolveNewton(const Model& model, SparseSystem* system, double tol, int max_iterations, double noise_floor,
                         const std::function<const StepContext&(int iteration)>& evaluate,
                         const std::function<double(const Eigen::VectorXd& increment)>& apply) {
  NewtonReport report;
  const int n_kinematic = model.num_unknowns() - model.num_multipliers();
  Eigen::VectorXd increment;
  bool increment_small = false;
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    report.iterations = iteration;
    system->Assemble(evaluate(iteration), true);
    const ResidualCheck check = CheckResidual(model, *system);
    report.force_residual = check.force;
    report.constraint_residual = check.constraint;
    report.worst_unknown = check.worst;
    if (!std::isfinite(check.force) || !std::isfinite(check.constraint)) return report;
    if (check.force <= tol && check.constraint <= kConstraintTolerance && increment_small) {
      report.converged = true;
      return report;
    }
    if (!system->Solve(&increment)) {
      report.singular = true;
      return report;
    }
    const double reference = apply(increment);
    increment_small =
        increment.head(n_kinematic).cwiseAbs().maxCoeff() <= tol * (reference + kIncrementFloor) + noise_floor;
  }
  return report;
}

}  // namespace flexmbd
