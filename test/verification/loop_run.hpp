#pragma once
// Runs a model with closed loops sample by sample and keeps what every loop test checks: the largest constraint
// value of any joint at any sample, and the energy books at the end.

#include <algorithm>
#include <cmath>
#include <functional>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {
namespace test {

struct LoopRun {
  double worst_constraint = 0;     // largest constraint value of any joint at any sample [m or rad]
  double books = 0;                // energy books at the end, relative to the energy throughput
  double worst_energy_change = 0;  // largest |E - E0| relative to the largest kinetic energy of the run
  OutputSample first, last;
  int steps = 0;
};

// Runs `model` to its end, handing each sample to `each` (with the state it was taken from).
inline LoopRun RunLoop(const Model& model, const std::function<void(const OutputSample&, const State&)>& each = {}) {
  Simulation simulation(model);
  StepContextBuilder builder(model);
  LoopRun run;
  double worst_energy_change = 0, largest_kinetic = 0;
  simulation.Run([&](const OutputSample& s) {
    if (run.steps++ == 0) run.first = s;
    if (each) each(s, simulation.state());
    const StepContext& ctx = builder.AtState(simulation.state());
    for (const Joint* joint : model.joints()) {
      if (joint->num_constraints() > 0) {
        run.worst_constraint = std::max(run.worst_constraint, joint->ConstraintValues(ctx).cwiseAbs().maxCoeff());
      }
    }
    worst_energy_change = std::max(worst_energy_change, std::abs(s.total() - run.first.total()));
    largest_kinetic = std::max(largest_kinetic, s.kinetic);
    run.last = s;
  });
  run.worst_energy_change = worst_energy_change / largest_kinetic;
  const OutputSample &f = run.first, &l = run.last;
  run.books = (l.total() + l.dissipated + l.numerical_dissipation - l.external_work - f.total()) /
              (std::abs(f.total()) + l.kinetic + l.dissipated + l.numerical_dissipation + std::abs(l.external_work));
  return run;
}

}  // namespace test
}  // namespace flexmbd
