#include "flexmbd/solver/start_sample.hpp"

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/sticking_redundancy.hpp"
#include "flexmbd/solver/velocity_projection.hpp"

namespace flexmbd {
namespace {
// The step's mean forces are the start's to O(h F'), 1e-3 of what one first step changes them by (the generalized-
// alpha starter's fraction); its motion stays far above the constraint tolerance.
constexpr double kVanishingStepFraction = 1.0e-3;
}  // namespace

OutputSample StartSample(const Model& model, const State& state, double h) {
  // A system of its own: the run's factorisations keep the pivot order of its own first step.
  SparseSystem system(model);
  StepContextBuilder builder(model);
  std::vector<EffectState> modes = state.effects;
  StickingRedundancy(model).Mark(state, &modes);
  builder.set_effect_modes(&modes);
  const StepContext* step = SolveLimitingStep(model, &system, &builder, state, kVanishingStepFraction * h);
  if (step == nullptr) return MakeSample(model, state, builder.AtState(state), 0.0, 0);
  State with_forces = state;
  with_forces.lambda = *step->lambda;
  return MakeSample(model, with_forces, *step, 0.0, 0);
}

}  // namespace flexmbd
