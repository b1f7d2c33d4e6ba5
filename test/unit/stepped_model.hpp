#pragma once
// A model stepped a few times at its solver dt, and a SparseSystem of its own to assemble at the context of the
// last Newton iteration: where the tests of the Newton loop's assembly start.

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/sparse_system.hpp"

namespace flexmbd {
namespace test {

struct SteppedModel {
  SteppedModel(const ModelSpec& spec, int steps) : model(BuildModel(spec)), simulation(model), system(model) {
    for (int k = 0; k < steps; ++k) simulation.TryStep(model.solver().dt);
  }
  SteppedModel(const SteppedModel&) = delete;
  SteppedModel& operator=(const SteppedModel&) = delete;
  const StepContext& ctx() const { return simulation.last_context(); }

  const Model model;
  Simulation simulation;
  SparseSystem system;
};

}  // namespace test
}  // namespace flexmbd
