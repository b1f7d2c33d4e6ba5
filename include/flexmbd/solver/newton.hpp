#pragma once
/// @file
/// Newton iteration shared by static and dynamic analyses (simplified: the tangent is refreshed only when
/// convergence is slow). Converged when the force rows are small relative to the magnitude of the forces that
/// make them up (or the correction computed from them is round-off in every unknown), the constraint rows are
/// below kConstraintTolerance, and the error left after the increment
/// computed from that residual (the increment, or less where the iteration's contraction was measured) is small
/// (for an approximate solve, that test alone: NewtonOptions); the increment is applied.

#include <functional>
#include <limits>

#include <Eigen/Core>

#include "flexmbd/elements/element.hpp"

namespace flexmbd {

class Model;
class SparseSystem;

/// Constraints hold to this absolute accuracy at every converged step [m or rad].
constexpr double kConstraintTolerance = 1.0e-11;
/// Smallest motion a static load step or an end-point step is judged against [m or rad]: keeps the increment
/// test meaningful when nothing moves.
constexpr double kMotionFloor = 1.0e-6;

struct NewtonReport {
  bool converged = false;
  bool singular = false;
  int iterations = 0;
  int tangents = 0;                ///< iterations that assembled and factorised a fresh tangent
  double force_residual = 0;       ///< relative, at the last evaluation
  double constraint_residual = 0;  ///< [m or rad]
  int worst_unknown = -1;          ///< row with the largest scaled residual
  int singular_unknown = -1;       ///< when singular: the unknown with the zero pivot, if the factorisation found it
  /// theta / (1 - theta) of the last contraction measured on one factorisation; NaN if none was measured
  double contraction_factor = std::numeric_limits<double>::quiet_NaN();
};

/// How a solve starts and what it must reach.
struct NewtonOptions {
  /// Start from the system's current factorisation instead of assembling a tangent (it is refreshed as soon as
  /// the iteration contracts too slowly).
  bool reuse_tangent = false;
  /// Converged on the increment test alone, without the residual test of the iterate it came from: for an
  /// approximate solve that a full one continues (an energy-decaying step judging its dissipation terms).
  bool increment_test_only = false;
  /// For such a solve, theta / (1 - theta) to assume for its first increment, the error it leaves being that
  /// times the increment (NaN: unknown, the increment itself is the bound).
  double expected_contraction_factor = std::numeric_limits<double>::quiet_NaN();
  /// Assemble and factorise a fresh tangent at every iteration (full Newton), as a static solve does.
  bool fresh_tangent_every_iteration = false;
};

/// Round-off of a configuration with coordinates up to `magnitude` [m or rad]: increments below it are noise.
double RoundOffFloor(double magnitude);

/// @param noise_floor increments below this are round-off (see RoundOffFloor) whatever the tolerance.
/// @param evaluate builds the StepContext for the current trial unknowns at a given iteration (1-based),
/// saying whether the tangent will be assembled from it.
/// @param apply applies a Newton increment to the trial unknowns and returns the size (max norm) of the
/// kinematic motion against which increments are judged small, floor included (e.g. kMotionFloor).
NewtonReport SolveNewton(const Model& model, SparseSystem* system, double tol, int max_iterations, double noise_floor,
                         const std::function<const StepContext&(int iteration, bool with_tangent)>& evaluate,
                         const std::function<double(const Eigen::VectorXd& increment)>& apply,
                         const NewtonOptions& options = {});

}  // namespace flexmbd
