#pragma once
/// @file
/// Static equilibrium by Newton's method with load stepping: gravity and applied loads are raised in
/// `load_steps` equal increments, each solved to convergence from the previous one.

#include <string>

#include "flexmbd/model/state.hpp"
#include "flexmbd/solver/newton.hpp"

namespace flexmbd {

class Model;
class SparseSystem;

struct StaticResult {
  bool converged = false;
  int load_steps = 0;
  int iterations = 0;       ///< over all load steps
  NewtonReport last;        ///< report of the last Newton solve
  /// Set when the equilibrium found is refused (converged false): a joint variable it turns by more than a turn
  /// from the start, and that turn [rad]; or the stop (index into Model::stops()) it lies beyond, open.
  int turned_variable = -1;
  double turn = 0;
  int passed_stop = -1;
  /// Set when the iteration matrix was singular at a joint variable (its zero pivot) that only an open elastic stop
  /// could hold, in a model without the inertia to tell which stop the load pushes it onto.
  int undirected_variable = -1;
};

/// Solves for equilibrium at time state->t starting from *state; velocities are set to zero. An increment turns a
/// joint by at most half a radian and stops at an open stop it would pass (docs/theory.md, "Static increments"); an
/// equilibrium that turns a joint more than a turn from the start, or lies beyond an open rigid stop, is refused.
StaticResult SolveStatic(const Model& model, SparseSystem* system, State* state);

/// What a static analysis that did not converge did, in its own terms (load increments, Newton iterations, the
/// worst residual) and what to try, e.g. "static analysis failed in load increment 3 of 10 (load factor 0.3):
/// Newton did not converge in 20 iterations (solver.max_iterations); worst residual at joint variable slide
/// (force 0.5 relative, constraint 0); try ...".
std::string DescribeStaticFailure(const Model& model, const StaticResult& result);

}  // namespace flexmbd
