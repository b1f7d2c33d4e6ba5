#include "flexmbd/solver/velocity_projection.hpp"

#include <algorithm>
#include <limits>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/joint_rates.hpp"
#include "flexmbd/solver/newton.hpp"
#include "flexmbd/solver/output_sample.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {
namespace {
// True when `friction` has a sticking row and is stuck in `state`.
bool StuckIn(const State& state, const FrictionEffect& friction) {
  return friction.has_sticking_row() && state.effects[friction.slot()].mode == FrictionEffect::kSticking;
}

// The limiting steps are this fraction of the last step and twice it: small enough that the forces' share of
// their mean velocities (h a / 2) is extrapolated away to O(h^2), large enough that the positions they move stay
// far above the constraint tolerance.
constexpr double kLimitingStepFraction = 1.0e-4;
}  // namespace

VelocityProjection::VelocityProjection(const Model& model, SparseSystem* system)
    : model_(model), system_(system), builder_(model), redundancy_(model) {}

const StepContext* SolveLimitingStep(const Model& model, SparseSystem* system, StepContextBuilder* builder,
                                     const State& state, double h) {
  const int n_kinematic = model.num_unknowns() - model.num_multipliers();
  const Eigen::VectorXd coasting = CoastingIncrements(model, state, h);
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model.num_unknowns());
  unknowns.head(n_kinematic) = coasting;
  const std::vector<NodeSchemeCoefficients> trapezoidal(model.num_nodes());
  system->set_factorisation_key(std::numeric_limits<double>::quiet_NaN());
  const NewtonReport report = SolveNewton(
      model, system, model.solver().tol, model.solver().max_iterations, NoiseFloor(model, state),
      [&](int, bool) -> const StepContext& { return builder->Dynamic(state, unknowns, h, trapezoidal); },
      [&](const Eigen::VectorXd& increment) {
        unknowns += increment;
        return (unknowns.head(n_kinematic) - coasting).cwiseAbs().maxCoeff() + h * kMotionFloor;
      });
  system->set_factorisation_key(std::numeric_limits<double>::quiet_NaN());
  if (!report.converged) return nullptr;
  return &builder->Dynamic(state, unknowns, h, trapezoidal);
}

bool VelocityProjection::SolveLimitingStep(const State& state, double h, MeanMotion* mean) {
  const StepContext* limit = flexmbd::SolveLimitingStep(model_, system_, &builder_, state, h);
  if (limit == nullptr) return false;
  const StepContext& ctx = *limit;
  mean->v.resize(model_.num_nodes());
  mean->w.resize(model_.num_nodes());
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeStep& s = (*ctx.nodes)[k];
    mean->v[k] = 0.5 * (s.v_i + s.v_f);
    mean->w[k] = 0.5 * (s.w_i + s.w_f);
  }
  mean->work = StepWork();
  for (const auto& element : model_.elements()) element->AddStepWork(ctx, &mean->work);
  mean->effect_dissipation.assign(model_.modal_effects().size(), 0.0);
  for (const ModalEffect* effect : model_.modal_effects()) {
    StepWork work;
    effect->AddStepWork(ctx, &work);
    mean->effect_dissipation[effect->slot()] = work.dissipated;
  }
  return true;
}

void VelocityProjection::HoldStuckJoints(const State& state) {
  // Released, a joint stuck at rest would slide the way its round-off rate points.
  for (const FrictionEffect* friction : model_.friction_effects()) {
    if (!StuckIn(state, *friction)) continue;
    modes_[friction->slot()].mode = FrictionEffect::kSticking;
    judged_[friction->slot()] = true;
  }
}

bool VelocityProjection::HoldStoppedSlides(const State& state, double h) {
  const auto& frictions = model_.friction_effects();
  const bool sliding = std::any_of(frictions.begin(), frictions.end(), [&](const FrictionEffect* friction) {
    return friction->has_sticking_row() && modes_[friction->slot()].mode != FrictionEffect::kSticking;
  });
  if (!sliding) return true;
  const StepContext* released = flexmbd::SolveLimitingStep(model_, system_, &builder_, state, h);
  if (released == nullptr) return false;
  // Read every slide before a mode changes: the context's trial modes are modes_.
  std::vector<int> stopped;
  for (const FrictionEffect* friction : frictions) {
    if (friction->SlideStoppedBy(*released)) stopped.push_back(friction->slot());
  }
  for (const int slot : stopped) {
    modes_[slot].mode = FrictionEffect::kSticking;
    judged_[slot] = true;
  }
  if (!stopped.empty()) redundancy_.Mark(state, &modes_);
  return true;
}

bool VelocityProjection::JudgeAcrossJump(const State& state, double h) {
  if (!HoldStoppedSlides(state, h)) return false;
  if (std::none_of(judged_.begin(), judged_.end(), [](bool judged) { return judged; })) return true;
  if (flexmbd::SolveLimitingStep(model_, system_, &builder_, state, h) == nullptr) return false;
  bool revised = false;
  for (const FrictionEffect* friction : model_.friction_effects()) {
    if (!judged_[friction->slot()]) continue;
    const int mode = friction->ModeAcrossImpulse(builder_.context());
    revised = revised || mode != modes_[friction->slot()].mode;
    modes_[friction->slot()].mode = mode;
  }
  if (revised) redundancy_.Mark(state, &modes_);
  return true;
}

bool VelocityProjection::Apply(State* state, const std::vector<bool>& held) {
  return Project(state, held, kLimitingStepFraction * state->h_prev, nullptr, Removed::kNumerical);
}

bool VelocityProjection::ApplyAtDriveJump(State* state, const Eigen::VectorXd& before, const Eigen::VectorXd& after,
                                          double h) {
  // The projection is linear in the drives' rates, so projecting onto `before` first changes nothing of the result;
  // it splits the books: what it removes is the alternating mode e the velocities carried, the scheme's; the second
  // projection then starts from velocities that meet every constraint, whose reactions do no work across it but the
  // drives', which do the jump's work (docs/theory.md, "Jumps of a drive's rate").
  const std::vector<bool> nothing_held(model_.modal_effects().size(), false);
  State projected = *state;
  if (!Project(&projected, nothing_held, kLimitingStepFraction * h, &before, Removed::kNumerical) ||
      !Project(&projected, nothing_held, kLimitingStepFraction * h, &after, Removed::kDrivesWork)) {
    return false;
  }
  // The jump is an impulse: a joint stuck before it, or whose slide it stops, sticks or slides as Coulomb's law for
  // impulses says (F8).
  for (const FrictionEffect* friction : model_.friction_effects()) {
    if (judged_[friction->slot()]) {
      FrictionEffect::EnterAfterImpulse(modes_[friction->slot()].mode, &projected.effects[friction->slot()]);
    }
  }
  *state = std::move(projected);
  return true;
}

bool VelocityProjection::Project(State* state, const std::vector<bool>& held, double h,
                                 const Eigen::VectorXd* drive_rates, Removed removed) {
  modes_ = state->effects;
  for (const ModalEffect* effect : model_.modal_effects()) {
    if (!held[effect->slot()]) modes_[effect->slot()].mode = effect->ReleasedMode(*state);
  }
  // At a jump of the drives' rates the frictions stuck before it, and those whose slide it stops, are judged (F8).
  const bool at_jump = drive_rates != nullptr;
  judged_.assign(modes_.size(), false);
  if (at_jump) HoldStuckJoints(*state);
  redundancy_.Mark(*state, &modes_);
  builder_.set_effect_modes(&modes_);
  builder_.set_drive_rates(drive_rates);
  MeanMotion single, twice;
  const bool converged = (!at_jump || JudgeAcrossJump(*state, h)) && SolveLimitingStep(*state, h, &single) &&
                         SolveLimitingStep(*state, 2.0 * h, &twice);
  builder_.set_drive_rates(nullptr);
  if (!converged) return false;
  // Richardson extrapolation to h = 0 of the mean velocities and of the constraint impulses' work.
  const double kinetic_before = StateEnergy(model_, *state).kinetic;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    state->nodes[k].v = 2.0 * single.v[k] - twice.v[k];
    state->nodes[k].w = 2.0 * single.w[k] - twice.w[k];
  }
  state->qdot = JointRates(model_, *state);
  // The limiting step reverses the inconsistent part e of the velocities, and its mean keeps half of that
  // step's work (the drives' impulses, friction); the kinetic energy of e, e^T M e / 2 >= 0, is what the
  // projection dissipates.
  auto kept = [](double single_step, double double_step) { return 0.5 * (2.0 * single_step - double_step); };
  const double external = kept(single.work.external, twice.work.external);
  double dissipated = kept(single.work.dissipated, twice.work.dissipated);
  for (size_t k = 0; k < state->effects.size(); ++k) {
    // Extrapolated from two steps that move by O(h) with finite forces (no impulse), an effect's work O(h^2) comes
    // out below zero; what it keeps of an impulse's is not. The part below zero is the projection's (F9).
    const double share = kept(single.effect_dissipation[k], twice.effect_dissipation[k]);
    state->effects[k].work += std::max(share, 0.0);
    dissipated -= std::min(share, 0.0);
  }
  const double kinetic_removed = kinetic_before - StateEnergy(model_, *state).kinetic;
  state->dissipated_physical += dissipated;
  if (removed == Removed::kDrivesWork) {
    state->external_work += dissipated - kinetic_removed;
  } else {
    state->external_work += external;
    state->dissipated_numerical += kinetic_removed + external - dissipated;
  }
  return true;
}

}  // namespace flexmbd
