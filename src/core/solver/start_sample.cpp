#include "flexmbd/solver/start_sample.hpp"

#include <type_traits>
#include <vector>

#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/effects/modal_effect.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/sticking_redundancy.hpp"
#include "flexmbd/solver/velocity_projection.hpp"

namespace flexmbd {
namespace {
// The steps' mean forces are the start's to O(h F'), 1e-3 of what one first step changes them by (the generalized-
// alpha starter's fraction), extrapolated to O(h^2); their motion stays far above the constraint tolerance.
constexpr double kVanishingStepFraction = 1.0e-3;
// Mode revisions of that step, as a step allows them (a stop and a friction may each change once or twice).
constexpr int kMaxModeRevisions = 4;

// The sample of `state` with the mean forces of one step of size `step` from it, in the modes that step takes, revised
// as a step revises them (a stuck joint whose load exceeds its static bound slides from the start: in the state's
// mode its sticking force broke the bound (F3) 1.5-130 times); the state's own multipliers if it does not converge.
OutputSample VanishingStepSample(const Model& model, SparseSystem* system, const State& state, double step,
                                 std::vector<EffectState>* modes) {
  StepContextBuilder builder(model);
  builder.set_effect_modes(modes);
  StickingRedundancy redundancy(model);
  const StepContext* ctx = nullptr;
  for (int revisions = 0; revisions <= kMaxModeRevisions; ++revisions) {
    redundancy.Mark(state, modes);
    ctx = SolveLimitingStep(model, system, &builder, state, step);
    if (ctx == nullptr) return MakeSample(model, state, builder.AtState(state), 0.0, 0);
    bool revised = false;
    for (const ModalEffect* effect : model.modal_effects()) {
      const int mode = effect->ReviseMode(*ctx);
      revised = revised || mode != (*modes)[effect->slot()].mode;
      (*modes)[effect->slot()].mode = mode;
    }
    if (!revised) break;
  }
  // The stops read the modes the step took: a joint that a load presses onto a stop it touches at rest is in contact
  // from the start, its force the step's multiplier (the state itself has the stop open). A joint's friction keeps
  // the state's mode: `sticking` says whether it is stuck at the instant, and one at rest that breaks away is.
  State with_forces = state;
  with_forces.lambda = *ctx->lambda;
  for (const JointStop* stop : model.stop_effects()) {
    with_forces.effects[stop->slot()].mode = (*modes)[stop->slot()].mode;
  }
  return MakeSample(model, with_forces, *ctx, 0.0, 0);
}
}  // namespace

OutputSample StartSample(const Model& model, const State& state, double h) {
  // A system of its own: the run's factorisations keep the pivot order of its own first step.
  SparseSystem system(model);
  std::vector<EffectState> modes = state.effects;
  const double step = kVanishingStepFraction * h;
  const OutputSample single = VanishingStepSample(model, &system, state, step, &modes);
  const OutputSample twice = VanishingStepSample(model, &system, state, 2.0 * step, &modes);
  // Richardson: the mean forces over the two steps, 2 single - twice (the line through them at u = -1), are those of
  // a step of length 0 (exact for forces linear in time, such as a ramp's); the state's own quantities are the same in
  // both and stay exact (2 x - x = x). The positions, stations' displacements and rotations, and the contacts' and
  // friction's states are single's; the stops' and friction's forces are extrapolated as the others.
  OutputSample start = single;
  MixLinearQuantities(single, twice, -1.0, &start);
  auto extrapolated = [](const auto& now, const auto& later) -> std::decay_t<decltype(now)> {
    return 2.0 * now - later;
  };
  // A stop never pulls (docs/theory.md (C2)), so its force at the start is >= 0; the line can cross zero where the
  // force is not linear in the step: an elastic stop touched at rest has forces that grow as h^2 from 0, extrapolated
  // to -2 c h^2 (-2.5e-5 N for a slider pressed by 5 N onto a stop of 1e5 N/m). Its error is that O(h^2) term.
  for (size_t k = 0; k < start.stops.size(); ++k) {
    const double force = extrapolated(single.stops[k].force, twice.stops[k].force);
    const bool pulls = force < 0.0;
    start.stops[k].force = pulls ? 0.0 : force;
    start.stops[k].torque = pulls ? 0.0 : extrapolated(single.stops[k].torque, twice.stops[k].torque);
  }
  for (size_t k = 0; k < start.friction.size(); ++k) {
    start.friction[k].torque = extrapolated(single.friction[k].torque, twice.friction[k].torque);
    start.friction[k].normal_force = extrapolated(single.friction[k].normal_force, twice.friction[k].normal_force);
  }
  return start;
}

}  // namespace flexmbd
