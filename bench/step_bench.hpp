#pragma once
// Times fixed-size steps of a model and reports the split of the cost per step (shared by the benchmarks).

#include <benchmark/benchmark.h>

#include <chrono>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/sparse_system.hpp"

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

// The cost of one Newton iteration of a dynamic step, split: assembly of residual and tangent, assembly of the
// residual alone (the simplified iterations), and one KLU refactorisation and solve of the same matrix, at the
// last iteration of the 20th step. Counters in microseconds per operation; iteration_over_klu =
// (tangent assembly + refactor and solve) / (refactor and solve), the figure of merit.
inline void TimeIteration(benchmark::State& state, const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  for (int k = 0; k < 20; ++k) simulation.TryStep(model.solver().dt);
  const StepContext& ctx = simulation.last_context();
  SparseSystem system(model);
  Eigen::VectorXd dx;
  system.Assemble(ctx, true);
  system.Solve(&dx, true);  // symbolic analysis and first factorisation outside the timing
  using Clock = std::chrono::steady_clock;
  double tangent = 0, residual = 0, klu = 0;
  long count = 0;
  for (auto _ : state) {
    auto t0 = Clock::now();
    system.Assemble(ctx, true);
    auto t1 = Clock::now();
    if (!system.Solve(&dx, true)) state.SkipWithError("singular");
    auto t2 = Clock::now();
    system.Assemble(ctx, false);
    auto t3 = Clock::now();
    tangent += std::chrono::duration<double>(t1 - t0).count();
    klu += std::chrono::duration<double>(t2 - t1).count();
    residual += std::chrono::duration<double>(t3 - t2).count();
    ++count;
  }
  state.counters["tangent_assembly_us"] = 1e6 * tangent / count;
  state.counters["residual_assembly_us"] = 1e6 * residual / count;
  state.counters["klu_refactor_solve_us"] = 1e6 * klu / count;
  state.counters["iteration_over_klu"] = (tangent + klu) / klu;
  state.counters["unknowns"] = model.num_unknowns();
}

}  // namespace bench
}  // namespace flexmbd
