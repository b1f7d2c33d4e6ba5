#pragma once
/// @file
/// Coulomb friction in a revolute or prismatic joint (docs/theory.md, "Friction", (F1)-(F6)). The normal
/// force is the joint's radial reaction (its position multipliers across the motion axis) plus a preload,
/// N = |P lambda| + N0, and enters the Newton iteration with its derivative. With slip velocity v = rho qdot:
///   sliding   Q = -mu_k rho N s on q, s = +-1 the sliding direction, fixed over a step; a step in which the
///             velocity would reverse is redone sticking
///   sticking  q_f - q_i = h qdot_i / 2 enforced by a multiplier, the friction force Q = -lambda_t: the end
///             rate vanishes under the energy-preserving relation (the step that starts sticking absorbs the
///             kinetic energy of the slip speed below v0; later steps have q_f = q_i and do no work). The joint
///             stays stuck while |lambda_t| <= mu_s rho N, else the step is redone sliding in the direction of
///             lambda_t
/// A sliding joint whose slip speed at the end of a step is below v0 sticks from the next step on. A breakaway from
/// a steady stick is located within its step (F3'), and the step that slides first is no longer than the local
/// error test allows after the jump (F3''). In a step in
/// which a rigid stop of the joint is in contact the stop holds q (q_f = q_i): friction then does no work and
/// its torque is not determined, so it applies none, and a sticking constraint would repeat the stop's; the
/// joint sticks or slides from the next step as its speed after the contact says. The same holds in a step in which
/// the sticking row repeats the other constraint rows (a drive holding it through a closed loop, a crank's dead
/// centre: StickingRedundancy, (F7)). The
/// regularised law Q = -mu_k rho N (1 - exp(-|v|/v0)) sign(v) has no modes; the constant-torque law (URDF
/// <dynamics friction>) replaces mu rho N by a fixed bound.

#include <vector>

#include "flexmbd/effects/modal_effect.hpp"
#include "flexmbd/joints/joint.hpp"
#include "flexmbd/model/model_spec.hpp"
#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {

class FrictionEffect : public ModalEffect {
 public:
  enum Mode { kSticking = 0, kSlidingPositive = 1, kSlidingNegative = 2 };

  /// @param stick_multiplier the sticking multiplier (-1 for the regularised law, which has none)
  /// @param solver the run's settings: error_tol sets the sticking threshold without a given v0, and the local
  ///        error test bounds the step that breaks away (F3'')
  FrictionEffect(const FrictionSpec& spec, const Joint& joint, int variable_unknown, int stick_multiplier,
                int stick_multiplier_unknown, int joint_multiplier_unknown, int slot, const SolverSpec& solver);

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;
  int ReviseMode(const StepContext& ctx) const override;
  /// Sliding the way the joint moves (a joint at rest stays stuck: its rate is then consistent already).
  int ReleasedMode(const State& state) const override { return InitialMode(state.qdot[variable_]); }
  StepLimit Limit(const StepContext& ctx, const State& end) const override;
  bool LocatesEventsFromEndRates() const override { return true; }
  void Commit(const StepContext& ctx, const State& end, EffectState* effect) const override;

  /// The mode across an impulse (a jump of a drive's rate) of a joint stuck before it, or whose slide it stops
  /// (SlideStoppedBy), from the limiting step
  /// `stuck` of the velocity projection solved with the joint stuck: its forces are the impulses over the step's
  /// size. Stuck while the sticking impulse stays within mu_s rho times the normal impulse (Coulomb's law for
  /// impulses), else sliding the way the impulse pushes it; the trial mode where the row is left out (F8).
  int ModeAcrossImpulse(const StepContext& stuck) const;
  /// True where the joint slides in the limiting step `released` of the velocity projection at a jump of a drive's
  /// rate, solved with it sliding, and that step's mean rate (the rate after the jump) runs against the slide: the
  /// jump's impulse stops the slide, and kinetic friction held the slide's way would push the joint on across it. It
  /// is then judged as a joint stuck before the jump is (ModeAcrossImpulse, F8).
  bool SlideStoppedBy(const StepContext& released) const;
  /// Enters `mode` after an impulse: the force of a stick before it is no base for locating a breakaway (F3').
  static void EnterAfterImpulse(int mode, EffectState* effect);
  /// The initial mode for a starting rate: sliding in its direction, sticking at rest.
  static int InitialMode(double qdot) { return qdot > 0 ? kSlidingPositive : qdot < 0 ? kSlidingNegative : kSticking; }
  /// The sticking threshold v0 in force at a state: min(1%, 100 error_tol) of the largest slip speed seen (at least
  /// 1e-6 m/s), or the given v0 where that is lower [m/s].
  double StickingSpeed(const EffectState& effect) const;
  /// The joint's friction at `state`, which the step `step` led to (a static context at a state no step led to):
  /// whether it is stuck at that instant, and the friction and normal forces of the step, those its work was booked
  /// with. At the end of a step that slid to a stop the force is the kinetic one that stopped it, not the multiplier
  /// of the stick that begins there.
  FrictionSample Sample(const State& state, const StepContext& step) const;
  int variable() const { return variable_; }
  /// The law and its parameters as given.
  const FrictionSpec& spec() const { return spec_; }
  /// The sticking constraint's multiplier (its row among the constraint rows); -1 for the regularised law.
  int stick_multiplier() const { return stick_multiplier_; }
  bool has_sticking_row() const { return stick_multiplier_ >= 0; }
  /// The joint's rigid stops (their slots in State::effects), which hold q while in contact.
  void set_rigid_stop_slots(std::vector<int> slots) { rigid_stop_slots_ = std::move(slots); }
  /// The model's rigid stops on other variables (their slots): a contact one of them begins in a step is an impact,
  /// which can turn this joint's slip within the step however short it is (docs/theory.md (F2)).
  void set_impact_stop_slots(std::vector<int> slots) { impact_stop_slots_ = std::move(slots); }
  /// The kinetic friction force mu_k rho N (or the constant torque) with the joint's reactions at `state`: what
  /// friction applies against a slide either way, so it jumps by twice this where the slide reverses [N m or N].
  double KineticForce(const State& state) const;

 private:
  // The friction force on q over a step and its derivatives.
  struct StepForce {
    double normal = 0;                      ///< N [N]
    double force = 0;                       ///< Q, the generalised friction force on q [N m or N]
    double d_dq = 0;                        ///< dQ/dq_f (regularised law)
    Vec3 d_dlambda = Vec3::Zero();          ///< dQ/d(joint position multipliers)
  };
  StepForce Evaluate(const StepContext& ctx) const;
  // The sticking constraint's row, q_f - q_i - h qdot_i / 2 [rad or m].
  double StickingResidual(const StepContext& ctx) const;
  // The friction force on q over the step ctx: the sticking multiplier, the law's force, or 0 where friction acts
  // not (held, static) [N m or N].
  double AppliedForce(const StepContext& ctx) const;
  // The work done against the friction force over the step ctx, -Q dq [J]. Coulomb friction never does positive work,
  // and the part of this below zero is the scheme's: a mode or a mean force held over a step in which the slip
  // stopped or turned (F9). Only the part above zero is the friction's dissipation.
  double StepWorkAgainst(const StepContext& ctx) const;
  // N and dN/d(joint position multipliers) from the multipliers and the motion axis in W.
  double NormalForce(const Vec3& lambda, const Vec3& axis_W, Vec3* d_dlambda) const;
  Vec3 AxisW(const State& state) const;
  // Coulomb bound of the friction force with coefficient mu: mu rho N (or the constant torque).
  double Bound(double mu, double normal) const;
  // The static bound mu_s rho N with the joint multipliers of `lambda`, about the motion axis of `start`.
  double StaticBound(const Eigen::VectorXd& lambda, const State& start) const;
  // The bound with coefficient mu, the joint multipliers of `lambda` and the motion axis of `start`.
  double BoundAt(double mu, const Eigen::VectorXd& lambda, const State& start) const;
  int Direction(int mode) const { return mode == kSlidingPositive ? 1 : mode == kSlidingNegative ? -1 : 0; }
  // The regularised law's factor (1 - exp(-|v|/v0)) sign(v) at slip velocity v, and its derivative in *d_dv.
  double RegularisedFactor(double v, double* d_dv) const;
  // Where, as a fraction of the step ctx solved sticking, the friction force of a joint stuck before it reaches
  // the static bound (0 if at the start or before): the excess |lambda| - mu_s rho N on the line through the
  // mean forces of the step before and of this one, at their mid-steps (F3'). Infinity when the start was not a
  // steady stick, the excess does not grow, or it passes the bound by no more than it departs from the trend of
  // the two steps before (a vibrating force: the step's mean force judges it).
  double BreakawayFraction(const StepContext& ctx) const;
  // True in a step that began stuck and is solved sliding: the static bound did not hold.
  bool BreakingAway(const StepContext& ctx) const;
  // True in a step solved sticking: the sticking constraint is enforced.
  bool Constrained(const StepContext& ctx) const;
  // True when a rigid stop of the joint is in contact in these effect modes (a step's trial modes or a state's),
  // or the joint sticks in them with its sticking row left out as a repeat of the other constraints (F7).
  bool Held(const std::vector<EffectState>& effects) const;
  // True when a rigid stop of another variable begins a contact in this step (an impact).
  bool ImpactInStep(const StepContext& ctx) const;
  // The slip speed at the end of the step ctx that F4 captures and F5 bands judge [m/s]: the larger of the end
  // rate's and the mean rates' extrapolated to the end, u + (u - u_prev) h / (h + h_prev), u = dq / h at the
  // mid-step. After a step that left an unresolved mode's end rate, v_f = 2 u - v_i may be small while the
  // joint still slips at u (docs/theory.md (F4)).
  double EndSpeed(const StepContext& ctx, const State& end) const;
  // The mean rate dq / h of the step ctx, that of the step before it (the start rate before the first step) and
  // the time between their mid-steps [rad/s or m/s, s].
  struct MeanRates {
    double now = 0, before = 0, span = 0;
  };
  MeanRates StepMeanRates(const StepContext& ctx) const;
  // End rate of q from the scheme's relation over the step, 2 dq / h - qdot_i.
  static double EndRate(const StepContext& ctx, int variable);

  FrictionSpec spec_;
  SolverSpec solver_;
  double auto_sticking_fraction_;  ///< of the largest slip speed: the sticking threshold without a given v0
  int variable_;
  int parent_node_;
  Mat3 R_NJ_;
  Vec3 axis_J_;
  int joint_multiplier_;       ///< first position multiplier of the joint
  int stick_multiplier_;       ///< -1 when the law has none
  int local_joint_multipliers_;  ///< local index of the joint's first position multiplier
  std::vector<int> rigid_stop_slots_;
  std::vector<int> impact_stop_slots_;
};

}  // namespace flexmbd
