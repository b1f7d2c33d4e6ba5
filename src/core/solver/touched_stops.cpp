#include "flexmbd/solver/touched_stops.hpp"

#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/newton.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {

void CloseTouchedRigidStops(const Model& model, double round_off, State* state) {
  for (const JointStop* stop : model.stop_effects()) {
    EffectState& effect = state->effects[stop->slot()];
    if (!stop->rigid() || effect.mode != JointStop::kOpen) continue;
    if (stop->Gap(state->q[stop->variable()]) > round_off) continue;
    effect.mode = JointStop::kContact;
  }
}

State WithTouchedStopsDecided(const Model& model, const State& state) {
  State decided = state;
  CloseTouchedRigidStops(model, RoundOffFloor(model.length_scale()), &decided);
  // Each pass opens the closed stops whose force pulls and solves the motion again without them; a stop is never
  // closed again, so the passes end.
  StepContextBuilder builder(model);
  for (bool opened = true; opened;) {
    opened = false;
    const State motion = WithConsistentMotion(model, decided);
    const StepContext& at_state = builder.AtState(motion);
    for (const JointStop* stop : model.stop_effects()) {
      if (!stop->rigid() || motion.effects[stop->slot()].mode != JointStop::kContact) continue;
      if (stop->Sample(motion, at_state).force >= 0.0) continue;
      decided.effects[stop->slot()].mode = JointStop::kOpen;
      opened = true;
    }
  }
  return decided;
}

}  // namespace flexmbd
