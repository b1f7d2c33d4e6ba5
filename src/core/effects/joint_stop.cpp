#include "flexmbd/effects/joint_stop.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "flexmbd/effects/friction_effect.hpp"
#include "flexmbd/solver/newton.hpp"
#include "flexmbd/solver/step_controller.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {
namespace {
// A step from an open gap g_i that ends beyond the stop starts the contact when g_i is at most this fraction
// of the gap's change over the step; otherwise it is redone shorter to end just before the contact, so a
// contact never starts far from the stop (docs/theory.md, (C5)).
constexpr double kEventFraction = 0.05;
// Slowest approach speed taken as an elastic contact's reference speed [m/s]: below it the Hunt-Crossley
// damping chi = alpha_e / v_in of a resting contact would be unbounded.
constexpr double kMinReferenceSpeed = 1.0e-6;
// An elastic contact step whose change of approach speed exceeds its budget pi v_in / N by more than this
// factor is redone (N the steps per contact); below it the next step is shortened instead.
constexpr double kRejectRatio = 2.0;
// An elastic contact whose approach speed is below this fraction of its impact speed v_in is at rest (C6).
constexpr double kRestingFraction = 0.1;
// A contact step may be at most this many times as long as the one before: the force of a contact begins at zero
// and grows with the approach, so the change of rate a short first step sees says little of the next one's (a
// Hertz stop's over a step from the contact's start grows as h^2.5). Allowed h / ratio, fixed steps of 1 ms went
// from a first contact step of 0.13 ms to one of 1 ms across the deepest compression of a ball dropped 0.5 m onto
// a stop of 1e8 N/m^1.5, and lost 5% of its rebound speed.
constexpr double kContactGrowth = 2.0;
// Shrink beyond the budget's estimate when redoing, so the retry is not rejected again.
constexpr double kRetrySafety = 0.8;
constexpr double kPi = 3.14159265358979323846;
// A rigid impact slower than this fraction of the fastest one the stop has seen is plastic (C2a'): a joint
// pressed onto a stop then comes to rest on it instead of bouncing ever lower and faster (a Zeno sequence that
// no step size resolves). A faster one returns the approach speed; if the contact still holds over the next step
// (the load presses the joint back within it), that step brings it to rest. A contact moving slower than this
// fraction of the fastest impact is at rest.
constexpr double kPlasticFraction = 0.01;
// A contact step longer than its acceleration jump allows (C5') is redone after a landing that leaves this fraction
// of the allowed half step to the stop (the controller's safety factor), so that the centred step after it passes
// even if its estimate of the jump comes out a little larger.
constexpr double kJumpSafety = 0.9;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A static iteration gives an elastic stop in contact at least the law's stiffness at this fraction of the model's
// size (ElasticStop::StaticStiffness): deeper than stops are pressed (a pendulum of 1 kg at 1 m on a Hertz stop of
// 1e6 N/m^1.5 at 0.1 m: 2.1e-3 m of 2.2 m), so the iteration treats a stop at first touch as nearly rigid, and
// Newton's update in the force (StaticPosition) then puts the approach where the law carries the force.
constexpr double kTouchApproach = 1.0e-3;

// The first time [s] at which a gap [m] closing at `rate` [m/s] with a constant `acceleration` [m/s^2] reaches 0:
// the smaller positive root of gap + rate t + acceleration t^2 / 2, written 2 gap / (sqrt(rate^2 - 2 acceleration
// gap) - rate) so that it keeps its digits when the acceleration is small; infinity when the gap never closes.
double TimeToStop(double gap, double rate, double acceleration) {
  if (gap <= 0) return 0;
  const double discriminant = rate * rate - 2 * acceleration * gap;
  if (discriminant < 0) return kInfinity;
  const double denominator = std::sqrt(discriminant) - rate;
  return denominator > 0 ? 2 * gap / denominator : kInfinity;
}
}  // namespace

JointStop::JointStop(const StopSpec& spec, int variable, int slot, const SolverSpec& solver)
    : ModalEffect(slot),
      solver_(solver),
      variable_(variable),
      sign_(spec.side == StopSpec::Side::kLower ? 1.0 : -1.0),
      radius_(spec.radius),
      limit_(spec.limit),
      retraction_(spec.retraction) {}

bool JointStop::StartsFar(double g_i, double g_f) { return g_i > kEventFraction * (g_i - g_f); }

int JointStop::ReleasedMode(const State& state) const {
  const int mode = state.effects[slot()].mode;
  return mode == kContact ? kOpen : mode;
}

StepLimit JointStop::Limit(const StepContext& ctx, const State&) const {
  StepLimit limit;
  const VariableStep& q = (*ctx.variables)[variable_];
  const double g_i = Gap(q.q_i), g_f = Gap(q.q_f);
  // A joint on a beam node may move by a finite amount however short the step: its variable carries the alternating
  // mode of the node's rotation, which the midpoint equations of a node with little or no rotary inertia turn
  // around in any step. Its landings then never end within kEventFraction of the next step's gap change, and were
  // redone down to dt_min (docs/theory.md, (C5)). At dt_min the contact begins where it is.
  if (TrialMode(ctx) == kOpen && g_f < 0 && StartsFar(g_i, g_f) && ctx.h > solver_.dt_min) {
    limit.retry = std::max(kEventLanding * ctx.h * g_i / (g_i - g_f), solver_.dt_min);
  }
  return limit;
}

void JointStop::Commit(const StepContext& ctx, const State& end, EffectState* effect) const {
  if (ctx.start->effects[slot()].mode != kContact && effect->mode == kContact) ++effect->events;
  if (retraction_.variable < 0) return;
  const double speed = std::abs(end.qdot[retraction_.variable]);
  if (effect->mode == kOpen && speed > retraction_.retract_above) effect->mode = kRetracted;
  if (effect->mode == kRetracted && speed < retraction_.engage_below && Gap(end.q[variable_]) >= 0) {
    effect->mode = kOpen;
  }
}

RigidStop::RigidStop(const StopSpec& spec, int variable, int variable_unknown, int multiplier, int multiplier_unknown,
                     int slot, const SolverSpec& solver)
    : JointStop(spec, variable, slot, solver), multiplier_(multiplier) {
  unknowns_ = {variable_unknown, multiplier_unknown};
}

void RigidStop::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                            Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const double lambda = (*ctx.lambda)[multiplier_];
  if (TrialMode(ctx) != kContact) {
    r[1] += lambda;  // no contact: the multiplier vanishes
    return;
  }
  const VariableStep& q = (*ctx.variables)[variable()];
  const double force = GeneralisedForce(lambda);
  r[0] -= force;
  magnitude[0] += std::abs(force);
  // A step in contact keeps the gap at its start value, so the contact force does no work (an impact returns the
  // approach speed, (C2a)); one that must end at rest is brought there by the velocity projection after it
  // (C2a'). At rest (static analysis), and in a contact at rest, the gap closes.
  r[1] += ClosesGap(ctx) ? Gap(q.q_f) : Gap(q.q_f) - Gap(q.q_i);
}

bool RigidStop::ClosesGap(const StepContext& ctx) const {
  // A contact begins up to 5% of a step's travel short of the stop ((C5), (C5')), and keeping that gap left a joint
  // resting on its stop short of it by as much (3.4e-7 rad for the elbow of elbow_rests_on_rigid_stop.yaml, reported
  // in contact). Once the contact is at rest the gap closes over one step; the work the contact force does in it is
  // booked as the scheme's (AddStepWork) and the rate it leaves projected away (ComesToRest).
  return ctx.at_end() || RestsOnStop(*ctx.start, JointErrorFloor(solver_) / ctx.h);
}

bool RigidStop::RestsOnStop(const State& start, double negligible_rate) const {
  // Held at rest by the projection after an earlier step, and still at rest: a projection after a very short step
  // can leave a rate (its limiting steps move the joints by about the constraint tolerance), and a joint that moves
  // keeps its gap (C2a) until a projection has stopped it.
  const EffectState& effect = start.effects[slot()];
  return effect.mode == kContact && effect.held_at_rest && std::abs(start.qdot[variable()]) <= negligible_rate;
}

void RigidStop::AddStepWork(const StepContext& ctx, StepWork* work) const {
  if (ctx.at_end() || TrialMode(ctx) != kContact) return;
  // lambda (g_f - g_i) on the system: none where the gap is kept (C2a), -lambda g_i over the step that closes it.
  const VariableStep& q = (*ctx.variables)[variable()];
  work->numerical += (*ctx.lambda)[multiplier_] * (Gap(q.q_i) - Gap(q.q_f));
}

bool RigidStop::Rebounds(double closing, double fastest) { return closing >= kPlasticFraction * fastest; }

bool RigidStop::ComesToRest(const State& start, const State& end, double negligible_rate) const {
  const EffectState& before = start.effects[slot()];
  if (end.effects[slot()].mode != kContact) return false;
  if (before.mode != kContact) return !Rebounds(-GapRate(start.qdot[variable()]), before.reference);
  // A step that closed a resting contact's gap (ClosesGap) ends with the rate 2 g_i / h that the closing gave.
  if (RestsOnStop(start, negligible_rate) && std::abs(Gap(start.q[variable()])) > kConstraintTolerance) return true;
  const double rest_rate = std::max(negligible_rate, kPlasticFraction * before.reference);
  return std::abs(GapRate(end.qdot[variable()])) > rest_rate;
}

bool RigidStop::CentresImpact(const StepContext& ctx) const {
  const State& start = *ctx.start;
  const double closing = -GapRate(start.qdot[variable()]);
  if (!solver_.adaptive || !Rebounds(closing, start.effects[slot()].reference)) return false;
  // A load that presses the joint on the stop (the gap accelerating shut) turns its rebound back after a flight of
  // 2 closing / |acceleration|. A flight shorter than the step is not resolved at the step's pace: its contact step
  // (C5) lets the load turn it back and comes to rest (C2a'), where centring would resolve a Zeno sequence of ever
  // lower bounces one by one (the frictionless forearm: 4,543 steps and 342 contacts instead of 282 and 24).
  const double acceleration = GapRate(Acceleration(start));
  return acceleration >= 0 || 2 * closing > -acceleration * ctx.h;
}

bool RigidStop::CloseAfterLastStep(const State& state) const {
  const int v = variable();
  if (state.mean_qdot[1].size() <= v) return false;
  const double change = std::max(std::abs(state.mean_qdot[0][v]) * state.recent_h[0],
                                 std::abs(state.mean_qdot[1][v]) * state.recent_h[1]);
  return Gap(state.q[v]) <= kEventFraction * std::abs(GapRate(change));
}

double RigidStop::Acceleration(const State& state) const {
  const int v = variable();
  const auto& rates = state.mean_qdot;
  if (state.recent_h[1] > 0 && rates[1].size() > v) {
    return MeanRateDerivative(rates[0][v], rates[1][v], state.recent_h[0], state.recent_h[1]);
  }
  return state.qddot_prev.size() > v ? state.qddot_prev[v] : 0.0;
}

double RigidStop::CrossingTime(const StepContext& ctx) const {
  const VariableStep& q = (*ctx.variables)[variable()];
  const double g_i = Gap(q.q_i), rate = GapRate(q.qdot_i), h = ctx.h;
  // The constant acceleration that takes the gap from g_i at the start rate to the step's end.
  return TimeToStop(g_i, rate, 2 * (Gap(q.q_f) - g_i - h * rate) / (h * h));
}

bool RigidStop::Centred(const StepContext& ctx) const {
  // A contact step of h instead of twice the crossing time shifts the motion after it by their difference: at the
  // start rate, a shift in the joint that the local error test (T12) must accept.
  const double allowance = JointErrorScale(solver_, ctx.h, ctx.start->peak_joint_rate[variable()]);
  const double shift = std::abs((*ctx.variables)[variable()].qdot_i) * std::abs(ctx.h - 2 * CrossingTime(ctx));
  return shift <= allowance;
}

double RigidStop::LongestImpactStep(const StepContext& ctx, const State& end) const {
  if (friction_ == nullptr) return kInfinity;
  const State& start = *ctx.start;
  const int v = variable();
  const double qdot_i = start.qdot[v], kinetic = friction_->KineticForce(start);
  // The joint's effective inertia m from the contact step: the contact force Q_c, which replaces the kinetic friction
  // -sign(qdot_i) F_k of the approach (a held joint has no friction), turns the approach's acceleration a_1 into
  // the step's mean one, m ((qdot_f - qdot_i) / h - a_1) = Q_c + sign(qdot_i) F_k, the other forces alike in both.
  const double change = (end.qdot[v] - qdot_i) / ctx.h - Acceleration(start);
  const double force = GeneralisedForce((*ctx.lambda)[multiplier_]) + std::copysign(kinetic, qdot_i);
  if (!(change * force > 0)) return kInfinity;
  // The rebound reverses the friction: the acceleration jumps by 2 F_k / m, and a contact step centred on the stop
  // lets the rebound leave off by |jump| h / 2 in rate (and |jump| h^2 / 8 in position), an error the motion after it
  // carries on. The local error test (T12) lets the error grow by error_tol times the peak joint rate per unit time
  // (its relative part over a step), so the rate may be off by that much (C5').
  const double jump = 2 * kinetic * change / force;
  return 2 * solver_.error_tol * start.peak_joint_rate[v] / std::abs(jump);
}

StepLimit RigidStop::Limit(const StepContext& ctx, const State& end) const {
  const State& start = *ctx.start;
  if (!CentresImpact(ctx)) return JointStop::Limit(ctx, end);
  StepLimit limit;
  const VariableStep& q = (*ctx.variables)[variable()];
  const double g_i = Gap(q.q_i), g_f = Gap(q.q_f), h = ctx.h;
  const int mode = TrialMode(ctx);
  if (mode == kContact && start.effects[slot()].mode != kContact) {
    // A contact step too long for its acceleration jump: land first, leaving a centred step within the bound that
    // begins close to the stop (t_c = h / 2: the step was centred).
    const double longest = LongestImpactStep(ctx, end);
    if (h > longest && h > solver_.dt_min) limit.retry = std::max(0.5 * (h - kJumpSafety * longest), solver_.dt_min);
    return limit;
  }
  if (mode != kOpen) return limit;
  if (g_f < 0 && g_f < g_i) {
    // It crossed and did not begin the contact (ReviseMode): redone centred if it began close to the stop and
    // lasted longer than twice its crossing time, else landed just short of the stop (C5).
    const double crossing = CrossingTime(ctx);
    const double retry =
        CloseAfterLastStep(start) && 2 * crossing < h ? 2 * crossing : kEventLanding * h * g_i / (g_i - g_f);
    limit.retry = std::max(retry, solver_.dt_min);
    return limit;
  }
  // A step that ended close to the stop, closing on it: the next step, if it meets the stop, is centred on it at the
  // end's rate and acceleration.
  if (g_f > 0 && g_f < g_i && CloseAfterLastStep(end)) {
    const int v = variable();
    limit.next = std::max(2 * TimeToStop(g_f, GapRate(end.qdot[v]), GapRate(Acceleration(end))), solver_.dt_min);
  }
  return limit;
}

void RigidStop::Commit(const StepContext& ctx, const State& end, EffectState* effect) const {
  if (effect->mode == kContact && ctx.start->effects[slot()].mode != kContact) {
    effect->reference = std::max(effect->reference, -GapRate(ctx.start->qdot[variable()]));
  }
  JointStop::Commit(ctx, end, effect);
}

void RigidStop::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  if (TrialMode(ctx) != kContact) {
    J(1, 1) += 1.0;
    return;
  }
  J(0, 1) -= GeneralisedForce(1.0);
  J(1, 0) += GapRate(1.0);
}

int RigidStop::ReviseMode(const StepContext& ctx) const {
  const int mode = TrialMode(ctx);
  const VariableStep& q = (*ctx.variables)[variable()];
  const double g_i = Gap(q.q_i), g_f = Gap(q.q_f);
  // Only a closing gap begins a contact: a joint that a plastic impact left a round-off inside the stop and
  // that moves off it stays open. An impact with adaptive steps begins in a step that starts close to the stop
  // and has it at its midpoint (C5'), any other contact close to the stop (C5).
  if (mode == kOpen && g_f < 0 && g_f < g_i) {
    // (At dt_min the step cannot be redone shorter: it begins the contact where it is.)
    const bool begins = CentresImpact(ctx) ? g_i <= 0 || ctx.h <= solver_.dt_min ||
                                                        (CloseAfterLastStep(*ctx.start) && Centred(ctx))
                                                  : !StartsFar(g_i, g_f) || ctx.h <= solver_.dt_min;
    if (begins) return kContact;
  }
  // The step that closes a resting contact's gap may need the stop to pull the joint the rest of the way (2 g_i / h^2
  // beyond what the load gives when the step is short): it holds, where opening it left the joint to fall onto the
  // stop again and again at ever shorter steps (an elbow 7.6e-9 rad short of its stop, below dt_min at steps of
  // 1.5e-5 s). From the next step on the gap is closed and a pull opens the contact as always.
  const bool closing = !ctx.at_end() && ClosesGap(ctx) && std::abs(Gap(q.q_i)) > kConstraintTolerance;
  if (mode == kContact && (*ctx.lambda)[multiplier_] < 0 && !closing) return kOpen;
  return mode;
}

StopSample RigidStop::Sample(const State& state, const StepContext&) const {
  StopSample s;
  s.in_contact = state.effects[slot()].mode == kContact;
  s.force = s.in_contact ? state.lambda[multiplier_] : 0.0;
  s.torque = GeneralisedForce(s.force);
  return s;
}

ElasticStop::ElasticStop(const StopSpec& spec, int variable, int variable_unknown, int slot, const SolverSpec& solver,
                         double length_scale, bool algebraic)
    : JointStop(spec, variable, slot, solver),
      law_(spec),
      steps_per_contact_(spec.steps_per_contact),
      touch_stiffness_(law_.Stiffness(kTouchApproach * length_scale)),
      algebraic_(algebraic) {
  unknowns_ = {variable_unknown};
}

double ElasticStop::StaticStiffness(double a) const {
  return a >= 0 ? std::max(law_.Stiffness(a), touch_stiffness_) : 0.0;
}

double ElasticStop::StaticPosition(double q, double dq) const {
  const double a = -Gap(q), da = -GapRate(dq);
  const double force = law_.Force(a) + StaticStiffness(a) * da;
  if (a < 0 || force <= 0 || law_.linear()) return q + dq;
  return q + (law_.ApproachAt(force) - a) / -GapRate(1.0);
}

double ElasticStop::ReferenceSpeed(const StepContext& ctx) const {
  const VariableStep& q = (*ctx.variables)[variable()];
  const double remembered = ctx.start->effects[slot()].reference;
  const double speed = Approach(q.q_i) > 0 ? remembered : -GapRate(Rates(ctx).start);
  return std::max(speed, kMinReferenceSpeed);
}

ElasticStop::JudgedRates ElasticStop::Rates(const StepContext& ctx) const {
  const VariableStep& q = (*ctx.variables)[variable()];
  const State& start = *ctx.start;
  JudgedRates rates;
  rates.step = (q.q_f - q.q_i) / ctx.h;
  rates.start = q.qdot_i;
  for (size_t k = 0; k < rates.before.size(); ++k) {
    rates.before[k] = start.mean_qdot[k].size() > variable() ? start.mean_qdot[k][variable()] : 0.0;
  }
  if (!algebraic_ || start.history_steps < 3) return rates;
  // The step ends carry an alternating error +-x (x at this step's start): the mean rates of the steps before carry
  // 2x/h, -2x/h, 2x/h, and this step, whose midpoint equations turn it around, -2x/h.
  const std::array<double, 3>& h = start.recent_h;
  const double x = AlternatingOffset(rates.before[0], rates.before[1], rates.before[2], h);
  rates.step += 2 * x / ctx.h;
  for (size_t k = 0; k < rates.before.size(); ++k) rates.before[k] -= (k % 2 == 0 ? 2 : -2) * x / h[k];
  // The end rates carry the mode's velocity, 4x/h a step and more: the start's rate from the freed mean rates.
  rates.start = rates.before[0] + 0.5 * h[0] * MeanRateDerivative(rates.before[0], rates.before[1], h[0], h[1]);
  return rates;
}

ElasticStop::StepForce ElasticStop::Evaluate(const StepContext& ctx) const {
  StepForce f;
  if (TrialMode(ctx) == kRetracted) return f;
  const VariableStep& q = (*ctx.variables)[variable()];
  // Signed approaches -g: the discrete gradient and the approach rate span the whole step, also across the
  // instant the gap closes or opens.
  f.a_i = -Gap(q.q_i);
  f.a_f = -Gap(q.q_f);
  const double da_dq = -GapRate(1.0);
  double d_elastic = 0;
  f.elastic = law_.DiscreteForce(f.a_i, f.a_f, &d_elastic);
  f.reference_speed = ReferenceSpeed(ctx);
  const double chi = law_.damping_number() / f.reference_speed;
  if (ctx.at_end()) {
    // Static and end-point (eigen-analysis) evaluations move the start with the end (a_i = a_f): the force is
    // V'(a_f), whose derivative V''(a_f) is twice the discrete gradient's derivative in a_f alone at coincident
    // approaches. At the end point the Hunt-Crossley factor reads the end rate, which gives the damping part.
    const double factor = ctx.mode == AnalysisMode::kEndPoint ? 1.0 + chi * -GapRate(q.qdot_f) : 1.0;
    if (factor <= 0) return f;
    f.force = f.damped = f.elastic * factor;
    const double stiffness = ctx.mode == AnalysisMode::kStatic ? StaticStiffness(f.a_f) : 2.0 * d_elastic;
    f.d_dq_f = stiffness * factor * da_dq;
    f.d_dqdot_f = ctx.mode == AnalysisMode::kEndPoint ? f.elastic * chi * da_dq : 0.0;
    return f;
  }
  // Hunt-Crossley factor, never pulling (it stays positive over an exact impact: 1 - alpha_e e > 0).
  const double factor = 1.0 + chi * (f.a_f - f.a_i) / ctx.h;
  if (factor <= 0 || f.elastic == 0) return f;
  f.damped = f.elastic * factor;
  f.d_dq_f = (d_elastic * factor + f.elastic * chi / ctx.h) * da_dq;
  // The energy-decaying scheme's dissipation of the stop's stretch, as springs and beams have it ("High-frequency
  // damping and rho_inf"): alpha times the law's stiffness at the step's start approach (at touch from an open gap:
  // the linear law's k, Hertz's 0) times the approach's change less the lagged one. Its work is >= 0 where the
  // variable's alpha is on (the scheme's check); the force still never pulls.
  const double stiffness = q.alpha * law_.Stiffness(std::max(f.a_i, 0.0));
  const double scheme = stiffness * (f.a_f - f.a_i + GapRate(q.dq_lagged));
  f.force = std::max(f.damped + scheme, 0.0);
  if (f.force > 0) f.d_dq_f += stiffness * da_dq;
  else f.d_dq_f = 0;
  return f;
}

void ElasticStop::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                              Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const double force = GeneralisedForce(Evaluate(ctx).force);
  r[0] -= force;
  magnitude[0] += std::abs(force);
}

void ElasticStop::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  J(0, 0) -= GeneralisedForce(Evaluate(ctx).d_dq_f);
}

bool ElasticStop::HasRateParts(AnalysisMode mode) const { return mode == AnalysisMode::kEndPoint; }

void ElasticStop::AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                               Eigen::Ref<Eigen::MatrixXd>) const {
  D(0, 0) -= GeneralisedForce(Evaluate(ctx).d_dqdot_f);
}

void ElasticStop::AddEnergy(const State& state, const Vec3&, EnergyTally* tally) const {
  if (state.effects[slot()].mode != kRetracted) tally->potential += law_.Potential(Approach(state.q[variable()]));
}

void ElasticStop::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const StepForce f = Evaluate(ctx);
  work->dissipated += (f.damped - f.elastic) * (f.a_f - f.a_i);
  work->numerical += (f.force - f.damped) * (f.a_f - f.a_i);
}

ElasticStop::Onset ElasticStop::ContactOnset(const StepContext& ctx, const JudgedRates& rates) const {
  Onset onset;
  const State& start = *ctx.start;
  const VariableStep& q = (*ctx.variables)[variable()];
  // The gap closed in this step if it began open, else in the step before if that one began open (its start
  // walked back over its mean rate).
  int step = -1;
  if (Gap(q.q_i) >= 0) step = 0;
  else if (start.history_steps >= 1 && Gap(q.q_i - start.recent_h[0] * start.mean_qdot[0][variable()]) >= 0) step = 1;
  // The two steps before that one were free of the contact: their mean rates, which carry no alternating mode of the
  // end rates (T12), give the joint's acceleration then and its rate at the start of the step that closed the gap.
  if (step < 0 || start.history_steps < step + 2) return onset;
  const double near = rates.before[step], far = rates.before[step + 1];
  const double h_near = start.recent_h[step];
  onset.step = step;
  onset.acceleration = MeanRateDerivative(near, far, h_near, start.recent_h[step + 1]);
  onset.rate = near + 0.5 * h_near * onset.acceleration;
  return onset;
}

double ElasticStop::MeanRateChange(const StepContext& ctx, const Onset& onset, const JudgedRates& rates) const {
  const State& start = *ctx.start;
  const double rate = rates.step;
  // In the step that closes the gap the rate changes from the one the motion before brought it to: the mean rate is
  // the mean of the end rates. (The difference of this step's mean rate from the previous one's, scaled from their
  // span to this step, spreads a change that happens in this step over a previous step that may be far longer: a
  // 1.28 ms step that took a ball from the stop to past its deepest compression, after a 52 ms step of free fall,
  // was judged to change the rate by 0.08 m/s, not 3.4.)
  if (onset.step == 0) return 2.0 * (rate - onset.rate);
  // Later the mean rates dq/h of this step and the previous one (State::mean_qdot), whose difference spans
  // (h + h_prev)/2, scaled to one step: unlike end rates they carry no alternating mode of the trapezoidal
  // relation (docs/theory.md, (T12)), which after a stick-slip transition can be as large as the budget whatever
  // the step.
  if (start.mean_qdot[0].size() == 0) return 2.0 * (rate - rates.start);  // the first step
  return (rate - rates.before[0]) * ctx.h / (0.5 * (ctx.h + start.h_prev));
}

double ElasticStop::OnsetError(const StepContext& ctx, const Onset& onset, const JudgedRates& judged) const {
  const State& start = *ctx.start;
  // The estimate (T12) on the mean rates of this step and the two before it, where the steps before the contact
  // are replaced by steps of the contact's own pace (the size of the step that closed the gap), their rates those
  // of the motion before it: (T12) on the steps as taken divides a change of the newest step by the span of free
  // steps that may be a hundred times longer, and lets a step that crosses the whole contact pass.
  std::array<double, 3> h;
  std::array<double, 3> rates;
  rates[0] = judged.step;
  if (onset.step == 0) {
    h = {ctx.h, ctx.h, ctx.h};
    rates[1] = onset.rate - 0.5 * ctx.h * onset.acceleration;
    rates[2] = onset.rate - 1.5 * ctx.h * onset.acceleration;
  } else {
    const double h_closing = start.recent_h[0];
    h = {ctx.h, h_closing, h_closing};
    rates[1] = judged.before[0];
    rates[2] = onset.rate - 0.5 * h_closing * onset.acceleration;
  }
  const double error = ctx.h * ctx.h * ctx.h * std::abs(MeanRateThirdDerivative(rates[0], rates[1], rates[2], h)) / 12;
  return error / JointErrorScale(solver_, ctx.h, start.peak_joint_rate[variable()]);
}

StepLimit ElasticStop::Limit(const StepContext& ctx, const State& end) const {
  StepLimit limit = ContactLimit(ctx, end);
  // Like the landing (C5), the rules of a step that begins open ask for no step shorter than dt_min, and one at dt_min
  // stands: the alternating mode a joint on a beam node carries changes its rate by a finite amount however short the
  // step, and its contact's first step, judged by the budget (C6) on that change, was cut below any dt_min. Inside a
  // contact a step below dt_min is a contact too fast for it, and the run stops saying so; except on a variable that
  // moves with an algebraic rotation, whose rules inside a contact see what is left of that error at every step size.
  if (Gap((*ctx.variables)[variable()].q_i) < 0 && !algebraic_) return limit;
  if (limit.retry < ctx.h) {
    limit.retry = ctx.h > solver_.dt_min ? std::max(limit.retry, solver_.dt_min) : kInfinity;
  }
  limit.next = std::max(limit.next, solver_.dt_min);
  return limit;
}

StepLimit ElasticStop::ContactLimit(const StepContext& ctx, const State& end) const {
  StepLimit limit = JointStop::Limit(ctx, end);
  const StepForce f = Evaluate(ctx);
  if (f.a_i <= 0 && f.a_f <= 0) return limit;  // no contact in this step
  const JudgedRates rates = Rates(ctx);
  const Onset onset = ContactOnset(ctx, rates);
  // Resolve the impact in steps_per_contact steps: over an impact the approach speed turns from v_in to
  // -e v_in along about half a period, changing by at most pi v_in / N per step of 1/N of it.
  const double budget = kPi * f.reference_speed / steps_per_contact_;
  const double change = std::abs(GapRate(MeanRateChange(ctx, onset, rates)));
  // A step that starts far from the stop, over which the approach speed changes by more than its start value, is
  // only redone to land just before the stop (C5): the speed at its start says nothing of the impact's, which sizes
  // the contact's steps from there. (Judged by it, a joint released at rest in its gap, whose first step crossed
  // the gap, had its steps cut below any dt_min.)
  if (limit.retry < ctx.h && change > f.reference_speed) return limit;
  // A contact that begins at rest on the stop (a body started there: the gap closed and no approach speed) is no
  // impact: there is no speed to size its steps by, and the budget at the floor speed cut them below any dt_min.
  // The local error test, or the fixed step, sizes them. (A body released above its stop is judged as before.)
  if (f.a_i == 0 && f.reference_speed <= kMinReferenceSpeed) return limit;
  // With adaptive steps the local error test judges the first steps of a contact on the contact's own pace, as
  // (T12) judges the steps after them.
  if (solver_.adaptive && onset.step >= 0) {
    const double error = OnsetError(ctx, onset, rates);
    const double factor = StepController::BoundedSizeFactor(error);
    if (error > 1) limit.retry = std::min(limit.retry, factor * ctx.h);
    else limit.next = std::min(limit.next, factor * ctx.h);
  }
  // Only the step that begins the contact is judged by the budget when the local error test (T12) resolves the rest
  // of it. With fixed steps a contact that has come to rest (approach speed below a tenth of v_in at the start of
  // the step) has no budget: inside a contact a change of rate need not shrink with the step (a joint starting to
  // stick absorbs its slip in one step whatever its size), and a budget scaled by the impact speed could not be met.
  // Its steps only grow by kContactGrowth at most, as an impact passes through rest where it turns: the fixed step
  // of 1 ms that followed there crossed the second half of the ball's compression in one step.
  const bool begins = f.a_i <= 0;
  if (!begins && solver_.adaptive) return limit;
  const double speed_i = std::abs(GapRate(ctx.start->qdot[variable()]));
  if (!begins && speed_i < kRestingFraction * f.reference_speed) {
    limit.next = std::min(limit.next, kContactGrowth * ctx.h);
    return limit;
  }
  const double ratio = change / budget;
  if (ratio > kRejectRatio) limit.retry = std::min(limit.retry, kRetrySafety * ctx.h / ratio);
  else if (ratio > 0) limit.next = std::min(limit.next, ctx.h * std::min(1.0 / ratio, kContactGrowth));
  return limit;
}

void ElasticStop::Commit(const StepContext& ctx, const State& end, EffectState* effect) const {
  const StepForce f = Evaluate(ctx);
  if (effect->mode != kRetracted) effect->mode = f.a_f > 0 ? kContact : kOpen;
  if (f.a_i <= 0 && f.a_f > 0) effect->reference = f.reference_speed;
  effect->work += (f.damped - f.elastic) * (f.a_f - f.a_i);
  JointStop::Commit(ctx, end, effect);
}

StopSample ElasticStop::Sample(const State& state, const StepContext& step) const {
  StopSample s;
  if (state.effects[slot()].mode == kRetracted) return s;
  s.approach = Approach(state.q[variable()]);
  s.in_contact = s.approach > 0;
  // The step's force (C2b), which the effort holds; not V'(a_f) at the end, which the discrete gradient approaches
  // as the steps shrink. The step that opens the contact still applies a force.
  s.force = Evaluate(step).force;
  s.torque = GeneralisedForce(s.force);
  return s;
}

}  // namespace flexmbd
