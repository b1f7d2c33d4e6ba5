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


struct ResidualCheck {
  double force = 0, constraint = 0;
  double force_round_off = 0;  ///< largest round-off of a force row [N or N m]
  int worst = -1;
};

// A force row is converged when it is below tol times the force scale, beyond its round-off: the residual of
// row k cannot be computed more accurately than about eps sum_j |J_kj| |x_j| (RoundOffFloor on the model's
// length scale), which matters for stiff elements (beam axial rows: EA / L times eps times the coordinates).
ResidualCheck CheckResidual(const Model& model, const SparseSystem& system) {
  const Eigen::VectorXd& r = system.residual();
  const Eigen::VectorXd& m = system.magnitude();
  // Element-state rows (first-order equations in the element's own units) are judged against their own scale.
  const int n_second_order = model.element_state_unknown(0), n_states = model.num_element_states();
  const double scale = std::max(m.head(n_second_order).cwiseAbs().maxCoeff(), kForceFloor);
  const double state_scale =
      n_states > 0 ? std::max(m.segment(n_second_order, n_states).cwiseAbs().maxCoeff(), kForceFloor) : 1.0;
  const double coordinate_round_off = RoundOffFloor(model.length_scale());
  ResidualCheck check;
  double worst_scaled = -1;
  for (int k = 0; k < r.size(); ++k) {
    const bool force = model.is_force_row(k);
    const double round_off = coordinate_round_off * system.row_abs_sum()[k];
    const double beyond_noise = std::max(0.0, std::abs(r[k]) - round_off);
    if (force && !model.is_state_row(k)) check.force_round_off = std::max(check.force_round_off, round_off);
    const double row_scale = model.is_state_row(k) ? state_scale : scale;
    const double scaled = force ? beyond_noise / row_scale : std::abs(r[k]) / kConstraintTolerance;
    if (force) check.force = std::max(check.force, scaled);
    else check.constraint = std::max(check.constraint, std::abs(r[k]));
    if (scaled > worst_scaled) {
      worst_scaled = scaled;
      check.worst = k;
    }
  }
  return check;
}

// A residual whose Newton correction is round-off in every unknown is round-off itself, however it compares with
// the loads (docs/theory.md, "Newton iteration"): r = -J dx bounds each row by sum_j |J_kj| |dx_j|, the row's own
// round-off when the coordinates move by less than theirs, plus what the multipliers carry. Those balance the
// element forces, so they are known no better than the largest round-off of a force row. An unloaded model's
// residual is all such round-off, and relative to its zero load it never passed. The correction is applied, so
// the iterate returned has what was left removed to first order.
bool CorrectionIsRoundOff(const Model& model, const Eigen::VectorXd& increment, double kinematic_size,
                          double noise_floor, const ResidualCheck& check) {
  const int n_multipliers = model.num_multipliers();
  const double multiplier_size = n_multipliers > 0 ? increment.tail(n_multipliers).cwiseAbs().maxCoeff() : 0.0;
  return kinematic_size <= noise_floor && multiplier_size <= check.force_round_off;
}
}  // namespace

double RoundOffFloor(double magnitude) {
  // A hundred units in the last place: the noise of a few dozen operations on such coordinates.
  constexpr double kRoundOffUnits = 100.0;
  return kRoundOffUnits * std::numeric_limits<double>::epsilon() * std::max(1.0, magnitude);
}

NewtonReport SolveNewton(const Model& model, SparseSystem* system, double tol, int max_iterations, double noise_floor,
                         const std::function<const StepContext&(int iteration, bool with_tangent)>& evaluate,
                         const std::function<double(const Eigen::VectorXd& increment)>& apply,
                         const NewtonOptions& options) {
  // Simplified Newton: the tangent is assembled and factorised on the first iteration and again only when the
  // observed contraction predicts more than this many further iterations.
  constexpr double kMaxSimplifiedIterations = 3.0;
  NewtonReport report;
  const int n_kinematic = model.num_unknowns() - model.num_multipliers();
  Eigen::VectorXd increment, applied;
  bool refresh = !(options.reuse_tangent && system->has_factorisation());
  bool tangent_from_earlier_step = !refresh;
  double previous_size = std::numeric_limits<double>::infinity();
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    report.iterations = iteration;
    report.tangents += refresh ? 1 : 0;
    system->Assemble(evaluate(iteration, refresh), refresh);
    const ResidualCheck check = CheckResidual(model, *system);
    report.force_residual = check.force;
    report.constraint_residual = check.constraint;
    report.worst_unknown = check.worst;
    if (!std::isfinite(check.force) || !std::isfinite(check.constraint)) return report;
    if (!system->Solve(&increment, refresh)) {
      report.singular = true;
      report.singular_unknown = system->singular_unknown();
      return report;
    }
    const double size = increment.head(n_kinematic).cwiseAbs().maxCoeff();
    if (!refresh && size >= previous_size) {
      // The old tangent no longer contracts: refresh it. If it came from an earlier step, its first increment
      // was taken untested and can be far off (a fast mode that changed phase): go back before it.
      if (tangent_from_earlier_step) {
        applied *= -1.0;
        apply(applied);
      }
      refresh = true;
      continue;
    }
    tangent_from_earlier_step = tangent_from_earlier_step && !refresh;
    applied = increment;
    const double reference = apply(increment);
    // On the increment test alone only an increment from a fresh tangent, or one that contracted, is trusted.
    const bool increment_trusted = refresh || std::isfinite(previous_size);
    const bool residual_passes = (options.increment_test_only && increment_trusted) ||
                                 (check.force <= tol && check.constraint <= kConstraintTolerance) ||
                                 CorrectionIsRoundOff(model, increment, size, noise_floor, check);
    // The error left in the iterate: an iteration contracting at the rate theta leaves about
    // theta / (1 - theta) times its last increment (Hairer and Wanner, Solving ODEs II, sec. IV.8, (8.10)); the
    // rate is measured on increments of one factorisation, otherwise the increment itself is the bound.
    const double contraction = size / previous_size;
    const bool rate_measured = !refresh && std::isfinite(previous_size) && contraction < 1.0;
    if (rate_measured) report.contraction_factor = contraction / (1.0 - contraction);
    // An approximate solve's first increment may be judged on the rate its caller expects (options).
    const bool rate_expected = options.increment_test_only && !std::isfinite(previous_size) &&
                               std::isfinite(options.expected_contraction_factor);
    double remaining = size;
    if (rate_measured) remaining = size * report.contraction_factor;
    else if (rate_expected) remaining = size * options.expected_contraction_factor;
    const double target = tol * reference + noise_floor;
    if (residual_passes && remaining <= target) {
      report.converged = true;
      return report;
    }
    // Refresh the tangent when the simplified iteration would need too many more iterations at its observed
    // contraction rate (ibid.).
    refresh = options.fresh_tangent_every_iteration || contraction >= 1.0 ||
              std::log(target / size) / std::log(contraction) > kMaxSimplifiedIterations;
    previous_size = size;
  }
  return report;
}

}  // namespace flexmbd
