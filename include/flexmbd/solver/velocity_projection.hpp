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
/// constraints. The limit is extrapolated from two short steps. At a jump of a drive's rate the projection onto the
/// drives' new rates carries the motion across the jump, and what that changes of the kinetic energy is the drives'
/// work (docs/theory.md, "Jumps of a drive's rate").

#include <vector>

#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/sticking_redundancy.hpp"

namespace flexmbd {

class Model;
class SparseSystem;
struct State;

/// Solves a step of size h from `state` by the trapezoidal rule (no scheme dissipation), in the modes and with the
/// drive rates `builder` is set to; the context of its converged end, valid until `builder` is used again, or null if
/// Newton did not converge. With h -> 0 its mean velocities are the projection of the start velocities, and its mean
/// forces, where those meet the constraints, the start's own.
const StepContext* SolveLimitingStep(const Model& model, SparseSystem* system, StepContextBuilder* builder,
                                     const State& state, double h);

class VelocityProjection {
 public:
  VelocityProjection(const Model& model, SparseSystem* system);

  /// Projects the velocities of `state` (which stays in its modes) and books the kinetic energy it removes as
  /// numerical dissipation. Effects are released, except those whose slot is marked in `held` (a contact brought
  /// to rest: its constraint then holds in the projection too). False (state unchanged) if the limiting step did
  /// not converge.
  bool Apply(State* state, const std::vector<bool>& held);

  /// Carries the velocities of `state` across a jump of the drives' rates from `before` to `after` (per joint
  /// variable, DriveRates), effects released: first projects them onto the constraints with the drives at `before`,
  /// booked as Apply books it, then onto those with the drives at `after`, whose change of the kinetic energy is
  /// the drives' work, booked as external work. `h` is the step that follows, which scales the limiting steps.
  /// A friction stuck in `state`, or sliding in it and stopped by the jump's impulse, is held stuck, and stays stuck
  /// across the jump unless its sticking impulse passes mu_s rho times its normal impulse; it then slides the way the
  /// impulse pushes it. `state` takes these modes (F8).
  /// False (state unchanged) if a limiting step did not converge.
  bool ApplyAtDriveJump(State* state, const Eigen::VectorXd& before, const Eigen::VectorXd& after, double h);

 private:
  // Mean velocities of one short step from `state` and the work done over it.
  struct MeanMotion {
    std::vector<Vec3> v, w;
    StepWork work;
    std::vector<double> effect_dissipation;  ///< by effect slot: each one's share of work.dissipated
  };
  bool SolveLimitingStep(const State& state, double h, MeanMotion* mean);
  // What a projection's removal of kinetic energy is booked as: the scheme's (numerical dissipation), or the drives'
  // work (external) when the projection only carries consistent velocities across a jump of the drives' rates.
  enum class Removed { kNumerical, kDrivesWork };
  // The projection of the velocities of `state` with limiting steps of h and 2 h; the drives follow `drive_rates`
  // (null: their laws or set-points).
  bool Project(State* state, const std::vector<bool>& held, double h, const Eigen::VectorXd* drive_rates,
               Removed removed);
  // Sets the frictions stuck in `state` sticking in modes_, and marks them in judged_.
  void HoldStuckJoints(const State& state);
  // If a friction slides in modes_, solves a limiting step of size h in them, and sets sticking in modes_, and marks
  // in judged_, each whose slide it stops (FrictionEffect::SlideStoppedBy). False if the step did not converge.
  bool HoldStoppedSlides(const State& state, double h);
  // At a jump of the drives' rates, with the frictions stuck before it held (HoldStuckJoints): holds those whose slide
  // it stops too, solves a limiting step of size h with all of them held, and sets each to the mode Coulomb's law for
  // impulses gives it (F8). False if a step did not converge.
  bool JudgeAcrossJump(const State& state, double h);

  const Model& model_;
  SparseSystem* system_;
  StepContextBuilder builder_;
  StickingRedundancy redundancy_;
  std::vector<EffectState> modes_;  ///< the modes the last projection was solved in
  std::vector<bool> judged_;        ///< by slot: the frictions the last projection judged across a jump (F8)
};

}  // namespace flexmbd
