#include "flexmbd/effects/friction_effect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {
namespace {
// Without a given v0 the sticking threshold is a fraction of the largest slip speed seen (issue 5): this many
// times the local error tolerance, at most kMaxAutoStickingFraction. A joint captured at a slip speed up to v0
// sticks up to v0 / a early, which shifts the motion after it by a relative error of the order of v0 over the
// slip speed; following the tolerance keeps that error proportional to it (issue 13: on the free double
// pendulum with URDF friction the error stalled at 3e-4 rad from error_tol 1e-4 to 1e-6 with a fixed 1%, and
// fell 76x and 127x per 100x of tolerance with this). 1% at the default error_tol 1e-4, as before ...
constexpr double kStickingFractionPerTolerance = 100.0;
constexpr double kMaxAutoStickingFraction = 0.01;
// ... and at least this [m/s], so a joint that has not slid yet still has a threshold.
constexpr double kMinAutoStickingSpeed = 1.0e-6;
// Step-size rule near sticking (docs/theory.md, (F5)): for slip speeds up to band[k] v0 the velocity may
// change by target[k] v0 per step.
constexpr double kSpeedBands[] = {2.0, 5.0, 10.0, 20.0};
constexpr double kSpeedTargets[] = {0.5, 1.0, 2.5, 5.0};
// A slip that reverses within a step sticks there if its speed at the start was at most this many v0 (the
// impulse that stops it is then of the order of the friction force times the step); a faster one is
// redone shorter, ending at kEventLanding of the interpolated stop.
constexpr double kCaptureSpeeds = 2.0;
// A stuck joint whose friction force passes its static bound later than this fraction into the step is located:
// the step is redone to end at kEventLanding of the crossing, so the breakaway starts within a few percent of a
// step of its instant (F3'), as a stop's contact does (C5).
constexpr double kBreakawayEventFraction = 0.05;
// A step that breaks away longer than the local error test allows after the jump is redone with this fraction of
// that size (the controller's safety factor), so that the redone step passes even if its mean acceleration is a
// little larger.
constexpr double kStepAfterJumpSafety = 0.9;
// BreakawayFraction when the static bound is not reached.
constexpr double kNoBreakaway = std::numeric_limits<double>::infinity();

// True when a breakaway at this fraction of a step of size h lies far enough into it to be located by a shorter
// step; never in a step of dt_min, which breaks away where it is, as a stop's landing begins its contact (C5): a
// stuck joint that a stiff mode shakes has its force cross the bound at any step size (a slot at a flexible rail's tip
// after a rigid impact, located down to 8.7e-10 s at error_tol 1e-6).
bool BreakawayToLocate(double fraction, double h, double dt_min) {
  return fraction > kBreakawayEventFraction && fraction < 1.0 && h > dt_min;
}
}  // namespace

FrictionEffect::FrictionEffect(const FrictionSpec& spec, const Joint& joint, int variable_unknown, int stick_multiplier,
                               int stick_multiplier_unknown, int joint_multiplier_unknown, int slot,
                               const SolverSpec& solver)
    : ModalEffect(slot),
      spec_(spec),
      solver_(solver),
      auto_sticking_fraction_(std::min(kMaxAutoStickingFraction, kStickingFractionPerTolerance * solver.error_tol)),
      variable_(joint.first_variable()),
      parent_node_(joint.parent().node),
      R_NJ_(joint.parent().R_NJ),
      axis_J_(joint.kinematics().rotations.empty() ? joint.kinematics().translation_rates_Jp[0]
                                                   : joint.kinematics().rotations[0].axis_J),
      joint_multiplier_(joint.first_multiplier()),
      stick_multiplier_(stick_multiplier) {
  unknowns_ = {variable_unknown};
  if (stick_multiplier_ >= 0) unknowns_.push_back(stick_multiplier_unknown);
  local_joint_multipliers_ = num_local();
  for (int k = 0; k < 3; ++k) unknowns_.push_back(joint_multiplier_unknown + k);
}

Vec3 FrictionEffect::AxisW(const State& state) const {
  const Mat3 R_WJ = parent_node_ < 0 ? R_NJ_ : Mat3(state.nodes[parent_node_].R * R_NJ_);
  return R_WJ * axis_J_.normalized();
}

double FrictionEffect::NormalForce(const Vec3& lambda, const Vec3& axis_W, Vec3* d_dlambda) const {
  *d_dlambda = Vec3::Zero();
  if (spec_.law == FrictionSpec::Law::kConstantTorque) return 0.0;
  const Vec3 radial = lambda - axis_W * axis_W.dot(lambda);
  const double magnitude = radial.norm();
  if (magnitude > 0) *d_dlambda = radial / magnitude;  // d|P l|/dl = P l / |P l| (P symmetric, P P = P)
  return magnitude + spec_.preload;
}

double FrictionEffect::Bound(double mu, double normal) const {
  return spec_.law == FrictionSpec::Law::kConstantTorque ? spec_.torque : mu * spec_.radius * normal;
}

double FrictionEffect::StickingSpeed(const EffectState& effect) const {
  // A given v0 is the most the joint may stick early by: the tolerance's threshold governs where it is lower, so
  // that a tighter error_tol still catches the slip's stop closer to its instant (F4).
  const double from_tolerance = std::max(auto_sticking_fraction_ * effect.reference, kMinAutoStickingSpeed);
  return spec_.v0 > 0 ? std::min(spec_.v0, from_tolerance) : from_tolerance;
}

double FrictionEffect::RegularisedFactor(double v, double* d_dv) const {
  const double decay = std::exp(-std::abs(v) / spec_.v0);
  *d_dv = decay / spec_.v0;
  return (1.0 - decay) * (v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0);
}

bool FrictionEffect::Held(const std::vector<EffectState>& effects) const {
  const EffectState& own = effects[slot()];
  if (own.mode == kSticking && own.held_by_constraints) return true;
  return std::any_of(rigid_stop_slots_.begin(), rigid_stop_slots_.end(),
                     [&](int slot) { return effects[slot].mode == JointStop::kContact; });
}

bool FrictionEffect::ImpactInStep(const StepContext& ctx) const {
  return std::any_of(impact_stop_slots_.begin(), impact_stop_slots_.end(), [&](int slot) {
    return (*ctx.effects)[slot].mode == JointStop::kContact && ctx.start->effects[slot].mode != JointStop::kContact;
  });
}

bool FrictionEffect::BreakingAway(const StepContext& ctx) const {
  return ctx.start->effects[slot()].mode == kSticking && TrialMode(ctx) != kSticking;
}

FrictionEffect::MeanRates FrictionEffect::StepMeanRates(const StepContext& ctx) const {
  const State& start = *ctx.start;
  const VariableStep& q = (*ctx.variables)[variable_];
  MeanRates rates;
  rates.now = (q.q_f - q.q_i) / ctx.h;
  const bool has_history = start.h_prev > 0 && start.mean_qdot[0].size() > variable_;
  // Without a step before, the start rate stands in for its mean rate, half a step back: the line then ends at v_f.
  rates.before = has_history ? start.mean_qdot[0][variable_] : q.qdot_i;
  rates.span = has_history ? 0.5 * (ctx.h + start.h_prev) : 0.5 * ctx.h;
  return rates;
}

double FrictionEffect::EndSpeed(const StepContext& ctx, const State& end) const {
  const MeanRates rates = StepMeanRates(ctx);
  const double extrapolated = rates.now + (rates.now - rates.before) * 0.5 * ctx.h / rates.span;
  return spec_.radius * std::max(std::abs(end.qdot[variable_]), std::abs(extrapolated));
}

double FrictionEffect::EndRate(const StepContext& ctx, int variable) {
  const VariableStep& q = (*ctx.variables)[variable];
  return 2.0 * (q.q_f - q.q_i) / ctx.h - q.qdot_i;
}

FrictionEffect::StepForce FrictionEffect::Evaluate(const StepContext& ctx) const {
  StepForce f;
  const int mode = TrialMode(ctx);
  // Static and eigen-analysis (the end-point evaluations) leave friction out (docs/theory.md, "Friction").
  if (ctx.at_end() || Held(*ctx.effects) ||
      (mode == kSticking && spec_.law != FrictionSpec::Law::kRegularised)) {
    return f;
  }
  const Vec3 lambda = ctx.lambda->segment<3>(joint_multiplier_);
  Vec3 d_normal;
  f.normal = NormalForce(lambda, AxisW(*ctx.start), &d_normal);
  if (spec_.law == FrictionSpec::Law::kRegularised) {
    const VariableStep& q = (*ctx.variables)[variable_];
    double d_dv = 0;
    const double factor = RegularisedFactor(spec_.radius * (q.q_f - q.q_i) / ctx.h, &d_dv);
    f.force = -Bound(spec_.mu_k, f.normal) * factor;
    f.d_dq = -Bound(spec_.mu_k, f.normal) * d_dv * spec_.radius / ctx.h;
    f.d_dlambda = -spec_.mu_k * spec_.radius * factor * d_normal;
    return f;
  }
  const double s = Direction(mode);
  f.force = -Bound(spec_.mu_k, f.normal) * s;
  if (spec_.law != FrictionSpec::Law::kConstantTorque) f.d_dlambda = -spec_.mu_k * spec_.radius * s * d_normal;
  return f;
}

bool FrictionEffect::Constrained(const StepContext& ctx) const {
  return TrialMode(ctx) == kSticking && !ctx.at_end() && !Held(*ctx.effects);
}

void FrictionEffect::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const bool sticking = Constrained(ctx);
  if (stick_multiplier_ >= 0) {
    const double lambda = (*ctx.lambda)[stick_multiplier_];
    if (sticking) {
      r[0] += lambda;  // the friction force on q is -lambda
      magnitude[0] += std::abs(lambda);
      r[1] += StickingResidual(ctx);
    } else {
      r[1] += lambda;
    }
  }
  const double force = Evaluate(ctx).force;
  r[0] -= force;
  magnitude[0] += std::abs(force);
}

void FrictionEffect::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  const bool sticking = Constrained(ctx);
  if (stick_multiplier_ >= 0) {
    if (sticking) {
      J(0, 1) += 1.0;
      J(1, 0) += 1.0;
    } else {
      J(1, 1) += 1.0;
    }
  }
  const StepForce f = Evaluate(ctx);
  J(0, 0) -= f.d_dq;
  for (int k = 0; k < 3; ++k) J(0, local_joint_multipliers_ + k) -= f.d_dlambda[k];
}

double FrictionEffect::StickingResidual(const StepContext& ctx) const {
  const VariableStep& q = (*ctx.variables)[variable_];
  // A step's row brings the end rate to 0. In the limiting steps of a projection at a jump of a drive's rate the mean
  // rate is the rate after the jump, so the row holds the joint at rest over them, as a drive at rate 0 would: a
  // joint the jump stops from a slide is then at rest after it, not at half its rate before (F8).
  const double travel = ctx.drive_rates != nullptr ? 0.0 : 0.5 * ctx.h * q.qdot_i;
  return q.q_f - q.q_i - travel;
}

double FrictionEffect::AppliedForce(const StepContext& ctx) const {
  const bool sticking = Constrained(ctx) && stick_multiplier_ >= 0;
  return sticking ? -(*ctx.lambda)[stick_multiplier_] : Evaluate(ctx).force;
}

double FrictionEffect::StepWorkAgainst(const StepContext& ctx) const {
  const VariableStep& q = (*ctx.variables)[variable_];
  return -AppliedForce(ctx) * (q.q_f - q.q_i);
}

void FrictionEffect::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const double against = StepWorkAgainst(ctx);
  work->dissipated += std::max(against, 0.0);
  work->numerical += std::min(against, 0.0);  // the scheme's: the mode held over the step (F9)
}

int FrictionEffect::ReviseMode(const StepContext& ctx) const {
  const int mode = TrialMode(ctx);
  if (spec_.law == FrictionSpec::Law::kRegularised || Held(*ctx.effects)) return mode;
  if (mode == kSticking) {
    // In the step that starts sticking the multiplier is the mean friction force of a slip that stops within
    // the step and then holds; beyond the static bound, kinetic friction could not stop it in the step, which
    // is then solved sliding (F3). A joint already at rest in a sliding mode (a static analysis first) takes
    // one step stuck before its bound is judged.
    if (ctx.start->effects[slot()].mode != kSticking && (*ctx.variables)[variable_].qdot_i == 0.0) return mode;
    const double lambda = (*ctx.lambda)[stick_multiplier_];
    if (std::abs(lambda) <= StaticBound(*ctx.lambda, *ctx.start)) return mode;
    // Past the bound far into the step: stuck until the crossing, which Limit locates (F3').
    if (BreakawayToLocate(BreakawayFraction(ctx), ctx.h, solver_.dt_min)) return mode;
    return lambda > 0 ? kSlidingPositive : kSlidingNegative;
  }
  // A joint breaking away (it began the step stuck and its static bound did not hold) keeps sliding for the
  // step even if its slide reverses within it, as when it is pressed into a stiff contact: it has then come to
  // rest again at a new position, and sticks from the next step on (Commit). Solving it stuck again would only
  // exceed the bound again, and the step would chatter between the two modes.
  if (BreakingAway(ctx)) return mode;
  // A slip that reverses within the step sticks in it if it was slow enough to stick; a faster one is located
  // first (Limit).
  const double qdot_i = (*ctx.variables)[variable_].qdot_i;
  const double slip_i = spec_.radius * std::abs(qdot_i);
  const bool slow = slip_i <= kCaptureSpeeds * StickingSpeed(ctx.start->effects[slot()]);
  // A start rate against the slide, faster than a capture (velocities projected before a much shorter step,
  // "Velocity projection after jumps", can turn it), says that the slip stopped before the step: there is no stop
  // within it to locate, and the joint slides the way it moves. (A slower one is judged as a capture below.)
  if (!slow && Direction(mode) * qdot_i < 0) return InitialMode(qdot_i);
  return Direction(mode) * EndRate(ctx, variable_) < 0 && slow ? kSticking : mode;
}

int FrictionEffect::ModeAcrossImpulse(const StepContext& stuck) const {
  if (!Constrained(stuck)) return TrialMode(stuck);
  const double lambda = (*stuck.lambda)[stick_multiplier_];
  if (std::abs(lambda) <= StaticBound(*stuck.lambda, *stuck.start)) return kSticking;
  return lambda > 0 ? kSlidingPositive : kSlidingNegative;
}

bool FrictionEffect::SlideStoppedBy(const StepContext& released) const {
  const int slide = Direction(TrialMode(released));
  if (slide == 0 || !has_sticking_row() || Held(*released.effects)) return false;
  const VariableStep& q = (*released.variables)[variable_];
  return slide * (q.q_f - q.q_i) < 0;
}

void FrictionEffect::EnterAfterImpulse(int mode, EffectState* effect) {
  effect->mode = mode;
  effect->steady_force = effect->steady_excess_before = std::numeric_limits<double>::quiet_NaN();
}

double FrictionEffect::KineticForce(const State& state) const { return BoundAt(spec_.mu_k, state.lambda, state); }

double FrictionEffect::StaticBound(const Eigen::VectorXd& lambda, const State& start) const {
  return BoundAt(spec_.mu_s, lambda, start);
}

double FrictionEffect::BoundAt(double mu, const Eigen::VectorXd& lambda, const State& start) const {
  Vec3 unused;
  return Bound(mu, NormalForce(lambda.segment<3>(joint_multiplier_), AxisW(start), &unused));
}

double FrictionEffect::BreakawayFraction(const StepContext& ctx) const {
  const State& start = *ctx.start;
  // Only a steady stick has a force to extrapolate from: a step that began sliding and stuck within it carries
  // the impulse that stopped the slip.
  const double force_i = start.effects[slot()].steady_force;
  if (std::isnan(force_i) || !Constrained(ctx)) return kNoBreakaway;
  const double excess_i = std::abs(force_i) - StaticBound(start.lambda, start);
  const double excess_f = std::abs((*ctx.lambda)[stick_multiplier_]) - StaticBound(*ctx.lambda, start);
  if (excess_f <= excess_i) return kNoBreakaway;  // not pressing harder
  // The multipliers are the mean forces of their steps, taken at the mid-steps t - h_prev / 2 and t + h / 2.
  const double span = 0.5 * (start.h_prev + ctx.h);
  const double crossing = -0.5 * start.h_prev + span * -excess_i / (excess_f - excess_i);
  // A force that vibrates about its trend passes the bound on the line only by as much as the line can be trusted
  // to: where its excess at the step's end stays within the force's departure from the trend of the two steps
  // before, the crossing is no event to locate, and the step's mean force judges it (F3').
  const double excess_before = start.effects[slot()].steady_excess_before;
  if (!std::isnan(excess_before)) {
    const double span_before = 0.5 * (start.recent_h[1] + start.h_prev);
    const double trend = excess_i + (excess_i - excess_before) * span / span_before;
    const double excess_end = excess_f + (excess_f - excess_i) * 0.5 * ctx.h / span;
    if (excess_end <= std::abs(excess_f - trend)) return kNoBreakaway;
  }
  return std::max(0.0, crossing / ctx.h);
}

StepLimit FrictionEffect::Limit(const StepContext& ctx, const State& end) const {
  StepLimit limit;
  if (spec_.law == FrictionSpec::Law::kRegularised || Held(*ctx.effects)) return limit;
  if (TrialMode(ctx) == kSticking) {
    // Also a step whose mean force kept the bound may pass it before its end.
    const double fraction = BreakawayFraction(ctx);
    if (BreakawayToLocate(fraction, ctx.h, solver_.dt_min)) {
      limit.retry = std::max(kEventLanding * fraction * ctx.h, solver_.dt_min);
    }
    return limit;
  }
  const double v_i = ctx.start->qdot[variable_], v_f = end.qdot[variable_];
  if (BreakingAway(ctx) && !std::isnan(ctx.start->effects[slot()].steady_force)) {
    // After a steady stick, whose steps grew with no local error to hold them, the slide starts with a jump of the
    // acceleration and the local error estimate restarts (F3''). The jump is taken from mean rates, which do not
    // carry the alternating velocity mode of the end rates (T12).
    const Eigen::VectorXd& rates_before = ctx.start->mean_qdot[0];
    const double rate_before = rates_before.size() > variable_ ? rates_before[variable_] : 0.0;
    const VariableStep& q = (*ctx.variables)[variable_];
    const double jump = 2.0 * ((q.q_f - q.q_i) / ctx.h - rate_before) / ctx.h;
    const double longest = StepAfterJump(solver_, jump, ctx.start->peak_joint_rate[variable_]);
    if (ctx.h > longest) {
      limit.retry = kStepAfterJumpSafety * longest;
      return limit;
    }
  }
  // Redo the step to end just before the slip stops (linear in the rate), where it can stick gently; not where an
  // impact elsewhere turns it: a rigid stop's contact step reverses the motion whatever its length, and the landings
  // fell below any dt_min (a free four-bar's sliding rocker when its crank struck its stop, explore6). The step keeps
  // the slide's mode, and the next one starts sliding the way the joint then moves (ReviseMode). So does a step of
  // dt_min, whose landing would be shorter still, as a stop's landing (C5): a stiff mode turns a slip in any step (a
  // slot at the tip of a flexible rail of EA 1e9 after a rigid impact, at 1.6e5 m/s^2).
  if (Direction(TrialMode(ctx)) * v_f < 0 && !BreakingAway(ctx) && !ImpactInStep(ctx)) {
    if (ctx.h > solver_.dt_min) {
      limit.retry = std::max(kEventLanding * ctx.h * std::abs(v_i) / (std::abs(v_i) + std::abs(v_f)), solver_.dt_min);
    }
    return limit;
  }
  const double speed = EndSpeed(ctx, end), change = spec_.radius * std::abs(v_f - v_i);
  const double v0 = StickingSpeed(ctx.start->effects[slot()]);
  if (std::abs(v_f) >= std::abs(v_i) || change == 0) return limit;  // not slowing down
  // Never below dt_min, as the landings of stops (C5): the steps are v0 / |a|, and a slip that a stiff mode turns has
  // no bound on |a| (a slot at a flexible rail's tip after a rigid impact: 5e4 m/s^2, steps of 5e-8 s). A step of
  // dt_min then captures the slip, or lets it reverse where it is (F2).
  for (int k = 0; k < 4; ++k) {
    if (speed <= kSpeedBands[k] * v0) {
      limit.next = std::max(ctx.h * kSpeedTargets[k] * v0 / change, solver_.dt_min);
      break;
    }
  }
  return limit;
}

void FrictionEffect::Commit(const StepContext& ctx, const State& end, EffectState* effect) const {
  effect->work += std::max(StepWorkAgainst(ctx), 0.0);
  const bool steady = Constrained(ctx) && ctx.start->effects[slot()].mode == kSticking;
  const double no_force = std::numeric_limits<double>::quiet_NaN();
  const double force_before = ctx.start->effects[slot()].steady_force;
  effect->steady_excess_before = steady && !std::isnan(force_before)
                                     ? std::abs(force_before) - StaticBound(ctx.start->lambda, *ctx.start)
                                     : no_force;
  effect->steady_force = steady ? (*ctx.lambda)[stick_multiplier_] : no_force;
  const double speed = spec_.radius * std::abs(end.qdot[variable_]);
  effect->reference = std::max(effect->reference, speed);
  if (spec_.law == FrictionSpec::Law::kRegularised) return;
  // After a step held by a rigid stop or by the constraints its sticking row repeats (F7) the joint moves on, or
  // rests, as they left it; a breakaway whose slide reversed within the step came to rest in it. Each sticks, or
  // slides the way it now moves if it is faster than it could stick.
  const bool reversed_breakaway = BreakingAway(ctx) && Direction(effect->mode) * end.qdot[variable_] < 0;
  if (Held(*ctx.effects) || reversed_breakaway) {
    const bool slow = speed <= kCaptureSpeeds * StickingSpeed(*effect);
    effect->mode = slow ? kSticking : InitialMode(end.qdot[variable_]);
  } else {
    // A joint slowing down below v0 sticks from the next step on (one speeding up is breaking away). Both are read
    // from the mean rates too: end rates carry the alternating mode of the scheme (F4).
    const MeanRates rates = StepMeanRates(ctx);
    const bool slowing = std::abs(end.qdot[variable_]) < std::abs(ctx.start->qdot[variable_]) &&
                         std::abs(rates.now) < std::abs(rates.before);
    if (effect->mode != kSticking && slowing && EndSpeed(ctx, end) <= StickingSpeed(*effect)) effect->mode = kSticking;
  }
  if (effect->mode == kSticking && ctx.start->effects[slot()].mode != kSticking) ++effect->events;
}

FrictionSample FrictionEffect::Sample(const State& state, const StepContext& step) const {
  FrictionSample s;
  const EffectState& effect = state.effects[slot()];
  Vec3 unused;
  s.normal_force = NormalForce(step.lambda->segment<3>(joint_multiplier_), AxisW(*step.start), &unused);
  s.slip_velocity = spec_.radius * state.qdot[variable_];
  s.work = effect.work;
  s.sticking = spec_.law != FrictionSpec::Law::kRegularised && effect.mode == kSticking;
  s.torque = AppliedForce(step);
  s.step_stuck = Constrained(step) && has_sticking_row();
  return s;
}

}  // namespace flexmbd
