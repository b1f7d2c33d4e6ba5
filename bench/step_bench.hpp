#pragma once
// Times fixed-size steps of a model and reports the split of the cost per step (shared by the benchmarks).

#include <benchmark/benchmark.h>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace bench {

// Steps `spec` at its solver dt once per benchmark iteration; counters in microseconds per step.
inline void TimeSteps(benchmark::State& state, const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  long steps = 0, iterations = 0;
  for (auto _ : state) {
    const StepResult result = simulation.TryStep(model.solver().dt);
    if (result.status != StepStatus::kAccepted) state.SkipWithError("step not accepted");
    ++steps;
    iterations += result.newton.iterations;
  }
  const SparseSystem::Timing& t = simulation.system().timing();
  state.counters["assembly_us_per_step"] = 1e6 * t.assembly / steps;
  state.counters["factorisation_us_per_step"] = 1e6 * t.factorisation / steps;
  state.counters["solve_us_per_step"] = 1e6 * t.solve / steps;
  state.counters["unknowns"] = model.num_unknowns();
  state.counters["nonzeros"] = simulation.system().num_nonzeros();
  state.counters["newton_iterations_per_step"] = static_cast<double>(iterations) / steps;
}

}  // namespace bench
}  // namespace flexmbd
