#pragma once
/// @file
/// Static equilibrium by Newton's method with load stepping: gravity and applied loads are raised in
/// `load_steps` equal increments, each solved to convergence from the previous one.

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
};

/// Solves for equilibrium at time state->t starting from *state; velocities are set to zero.
StaticResult SolveStatic(const Model& model, SparseSystem* system, State* state);

}  // namespace flexmbd
