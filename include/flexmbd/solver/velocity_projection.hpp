#pragma once
/// @file
/// Removes the alternating velocity mode that the trapezoidal relation leaves after a jump in the motion
/// (docs/theory.md, "Velocity projection after jumps"). Constraints hold on positions only, so the node
/// velocities of a step can violate the velocity form of the constraints by an amount e that flips sign every
/// step; after an impact or a stick-slip transition e is of the order of the jump. A step much shorter than the
/// one that made it cannot carry it and turns it into an impulse ~ 1/h (the reactions, hence friction bounds,
/// follow), so an event could never be located by shortening the step. The consistent velocities are the mean
/// velocities (v_i + v_f)/2 of the scheme's own step in the limit h -> 0: that step has no forces but the
/// constraint impulses, and its mean is the mass-weighted projection of the start velocities onto the active
/// constraints. The limit is extrapolated from two short steps.

#include <vector>

#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/sticking_redundancy.hpp"

namespace flexmbd {

class Model;
class SparseSystem;
struct State;

class VelocityProjection {
 public:
  VelocityProjection(const Model& model, SparseSystem* system);

  /// Projects the velocities of `state` (which stays in its modes) and books the kinetic energy it removes as
  /// numerical dissipation. Effects are released, except those whose slot is marked in `held` (a contact brought
  /// to rest: its constraint then holds in the projection too). False (state unchanged) if the limiting step did
  /// not converge.
  bool Apply(State* state, const std::vector<bool>& held);

 private:
  // Mean velocities of one short step from `state` and the work done over it.
  struct MeanMotion {
    std::vector<Vec3> v, w;
    StepWork work;
    std::vector<double> effect_dissipation;  ///< by effect slot: each one's share of work.dissipated
  };
  bool SolveLimitingStep(const State& state, double h, MeanMotion* mean);

  const Model& model_;
  SparseSystem* system_;
  StepContextBuilder builder_;
  StickingRedundancy redundancy_;
};

}  // namespace flexmbd
