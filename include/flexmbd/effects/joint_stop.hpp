#pragma once
/// @file
/// Stops on a joint variable q (backlash, freeplay; docs/theory.md, "Stops", (C1)-(C6)). The gap is
/// g = s rho (q - q_stop), s = +1 for a lower stop and -1 for an upper one, rho the contact radius; the
/// contact force F >= 0 acts along dg/dq, a generalised force F s rho on q.
///   RigidStop    g >= 0. A step that ends with g_f < 0 is redone with g_f = g_i enforced by a multiplier,
///                the contact force, which does no work because the gap does not change over the step; a
///                step in contact whose multiplier would pull is redone open. With adaptive steps the step that
///                begins an impact has the stop at its midpoint and is no longer than its acceleration jump allows
///                (C5').
///   ElasticStop  F = V'(a) [1 + chi a_dot] at approach a = -g > 0 (ContactLaw), with the exact discrete
///                gradient of V so the books of stored and dissipated energy close.
/// A stop with a retraction rule stops acting at the first separation after a named variable's speed
/// exceeds a threshold and engages again below another.

#include <array>
#include <string>

#include "flexmbd/effects/contact_law.hpp"
#include "flexmbd/effects/modal_effect.hpp"
#include "flexmbd/model/model_spec.hpp"
#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {

class FrictionEffect;

class JointStop : public ModalEffect {
 public:
  enum Mode { kOpen = 0, kContact = 1, kRetracted = 2 };

  double Gap(double q) const { return sign_ * radius_ * (q - limit_); }  ///< [m]
  double GapRate(double qdot) const { return sign_ * radius_ * qdot; }   ///< [m/s]
  /// Generalised force on q of a contact force F [N m or N].
  double GeneralisedForce(double force) const { return sign_ * radius_ * force; }
  int variable() const { return variable_; }
  /// A unilateral constraint with a multiplier (RigidStop), or a force law of the approach (ElasticStop): what
  /// the static solver and the friction builder need to tell apart.
  virtual bool rigid() const = 0;

  /// The output record of the stop at `state`, reached by `step` (or StepContextBuilder::AtState): contact and
  /// approach at the state, force and torque those `step` applied, the stop's part of the joint's effort.
  virtual StopSample Sample(const State& state, const StepContext& step) const = 0;

  /// Open if in contact (a contact may always separate); an open or retracted stop keeps its mode.
  int ReleasedMode(const State& state) const override;
  /// Approach rule (C5): a step that crosses the stop from far is redone to land just short of it, never shorter than
  /// dt_min; one at dt_min begins the contact where it is.
  StepLimit Limit(const StepContext& ctx, const State& end) const override;
  /// Counts contacts begun and applies the retraction rule; derived classes add their memory.
  void Commit(const StepContext& ctx, const State& end, EffectState* effect) const override;

 protected:
  JointStop(const StopSpec& spec, int variable, int slot, const SolverSpec& solver);

  // True when a step from the gap g_i to g_f < 0 [m] began too far from the stop to begin a contact (C5).
  static bool StartsFar(double g_i, double g_f);

  SolverSpec solver_;

 private:
  int variable_;
  double sign_, radius_, limit_;
  StopSpec::Retraction retraction_;
};

class RigidStop : public JointStop {
 public:
  RigidStop(const StopSpec& spec, int variable, int variable_unknown, int multiplier, int multiplier_unknown, int slot,
            const SolverSpec& solver);
  bool rigid() const override { return true; }
  /// The joint's friction, whose force turns with the rebound (C5'); none by default.
  void set_friction(const FrictionEffect* friction) { friction_ = friction; }
  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  int ReviseMode(const StepContext& ctx) const override;
  /// The work of the contact force over a step that closes the gap, the scheme's (numerical).
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;
  /// A plastic impact, or a contact that goes on after its first step while the joint still moves or has closed
  /// its gap (C2a').
  bool ComesToRest(const State& start, const State& end, double negligible_rate) const override;
  /// The approach rule (C5); with adaptive steps an impact's contact step centred on the stop and bounded by its
  /// acceleration jump (C5').
  StepLimit Limit(const StepContext& ctx, const State& end) const override;
  /// Remembers the fastest impact.
  void Commit(const StepContext& ctx, const State& end, EffectState* effect) const override;
  StopSample Sample(const State& state, const StepContext& step) const override;

 private:
  // True when the contact row of the step ctx is g_f = 0 (a static analysis, a contact at rest) rather than
  // g_f = g_i (C2a).
  bool ClosesGap(const StepContext& ctx) const;
  // True when `start` is in a contact the velocity projection held at rest, and the joint's rate is still below
  // `negligible_rate` [rad/s or m/s] (C2a'').
  bool RestsOnStop(const State& start, double negligible_rate) const;
  // True when a contact begun with the gap closing at `closing` [m/s] rebounds, not a plastic impact that comes to
  // rest (C2a'); `fastest` is the fastest impact the stop has seen [m/s].
  static bool Rebounds(double closing, double fastest);
  // True when a contact begun from the start of ctx is an impact whose step is centred on the stop (C5'): adaptive
  // steps, a rebound, and a rebound flight longer than the step ctx.
  bool CentresImpact(const StepContext& ctx) const;
  // True when `state` lies within kEventFraction of the larger gap change of its last two steps of the stop, where
  // (C5') lets a contact step begin.
  bool CloseAfterLastStep(const State& state) const;
  // When [s] the gap of the step ctx, on the parabola through its ends at its start rate, reaches the stop.
  double CrossingTime(const StepContext& ctx) const;
  // True when the step ctx, which crosses the stop, lasts twice its crossing time to within the local error test's
  // allowance: as a contact step it returns the motion the exact impact has at its end (C5').
  bool Centred(const StepContext& ctx) const;
  // The longest contact step from the start of ctx (in contact) that its acceleration jump allows (C5') [s]:
  // infinity without friction or an estimate.
  double LongestImpactStep(const StepContext& ctx, const State& end) const;
  // The joint's acceleration at `state` from the mean rates of its last two steps [rad/s^2 or m/s^2].
  double Acceleration(const State& state) const;

  int multiplier_;
  const FrictionEffect* friction_ = nullptr;
};

class ElasticStop : public JointStop {
 public:
  /// @param solver the run's settings: with adaptive steps the local error test, on the stop's own pace at the
  /// onset of a contact, resolves it (C6); with fixed steps the contact rule (C6) bounds every contact step.
  /// @param length_scale the model's size [m], which sets the least stiffness a static iteration gives the stop in
  /// contact (StaticStiffness).
  /// @param algebraic the variable moves with an algebraic rotation (Model::moves_with_algebraic_rotation): the rules
  /// of the contact's steps read its rates freed of that rotation's alternating error.
  ElasticStop(const StopSpec& spec, int variable, int variable_unknown, int slot, const SolverSpec& solver,
              double length_scale, bool algebraic);
  bool rigid() const override { return false; }
  /// The stiffness dF/da [N/m] a static Newton iteration takes at the signed approach a [m] (docs/theory.md, "Static
  /// increments"): V''(a), touching or pressed at least the law's at an approach of kTouchApproach times the model's
  /// size, since Hertz's V'' vanishes at first touch and left the matrix singular.
  double StaticStiffness(double a) const;
  /// Where a static increment dq from the joint position q takes the joint: pressed on the stop (a >= 0), to the
  /// approach at which the law's force is the force the increment's linearisation predicts, V'(a) +
  /// StaticStiffness(a) da (Newton's update in the force, in which the law is linear); otherwise q + dq.
  double StaticPosition(double q, double dq) const;
  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  /// At the end point (eigen-analysis) the Hunt-Crossley factor reads the end rate: a damping part.
  bool HasRateParts(AnalysisMode mode) const override;
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                    Eigen::Ref<Eigen::MatrixXd> M) const override;
  void AddEnergy(const State& state, const Vec3& gravity, EnergyTally* tally) const override;
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;
  /// The force does not depend on the mode: the mode only records contact.
  int ReviseMode(const StepContext& ctx) const override { return TrialMode(ctx); }
  StepLimit Limit(const StepContext& ctx, const State& end) const override;
  /// Contact begins and ends at zero force.
  bool ModeChangesAreSmooth() const override { return true; }
  void Commit(const StepContext& ctx, const State& end, EffectState* effect) const override;
  StopSample Sample(const State& state, const StepContext& step) const override;

 private:
  // The contact force over a step and its derivative with respect to q_f.
  struct StepForce {
    double a_i = 0, a_f = 0;     ///< signed approaches -g [m] (negative: open)
    double elastic = 0;          ///< discrete gradient of V [N]
    double damped = 0;           ///< with the Hunt-Crossley factor [N]
    double force = 0;            ///< with the scheme's dissipation too [N]
    double d_dq_f = 0;           ///< d force / d q_f
    double d_dqdot_f = 0;        ///< d force / d qdot_f (end point only)
    double reference_speed = 0;  ///< v_in used [m/s]
  };
  StepForce Evaluate(const StepContext& ctx) const;
  double Approach(double q) const { return std::max(0.0, -Gap(q)); }  ///< [m], 0 when open
  // v_in of a step: the memory when in contact at its start, else the approach speed at its start.
  double ReferenceSpeed(const StepContext& ctx) const;
  // The joint's rates as the contact's rules read them: the mean rate of the step ctx, those of the three steps before
  // it (newest first) and the rate at its start. On a variable that moves with an algebraic rotation they are freed of
  // that rotation's alternating error, which moves the joint by a finite amount however short the step (docs/theory.md,
  // "Algebraic rotations"); elsewhere they are the mean rates and the start's end rate.
  struct JudgedRates {
    double step = 0;
    std::array<double, 3> before{};
    double start = 0;
  };
  JudgedRates Rates(const StepContext& ctx) const;
  // The joint's motion before the contact that is at most one step old in ctx, from mean rates (C6).
  struct Onset {
    int step = -1;            ///< the step in which the gap closed: 0 this one, 1 the one before; -1: none known
    double rate = 0;          ///< the joint's rate at that step's start [rad/s or m/s]
    double acceleration = 0;  ///< and its acceleration then [rad/s^2 or m/s^2]
  };
  Onset ContactOnset(const StepContext& ctx, const JudgedRates& rates) const;
  // The change of the joint's rate over the step ctx, from mean rates (C6).
  double MeanRateChange(const StepContext& ctx, const Onset& onset, const JudgedRates& rates) const;
  // The joint's local error over the step ctx at the onset of a contact, against its tolerance (C6).
  double OnsetError(const StepContext& ctx, const Onset& onset, const JudgedRates& rates) const;
  // The landing (C5), the onset's error (C6') and the budget (C6) on the step ctx, before Limit floors a retry at
  // dt_min.
  StepLimit ContactLimit(const StepContext& ctx, const State& end) const;

  ContactLaw law_;
  int steps_per_contact_;
  double touch_stiffness_;  ///< least static stiffness in contact [N/m] (StaticStiffness)
  bool algebraic_;          ///< the variable moves with an algebraic rotation
};

}  // namespace flexmbd
