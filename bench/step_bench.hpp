#pragma once
// Times fixed-size steps of a model and reports the split of the cost per step (shared by the benchmarks).

#include <benchmark/benchmark.h>

#include <algorithm>
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
// last iteration of the 20th step, with the elements evaluated on `threads` threads (solver.threads). Counters in
// microseconds per operation (wall clock: the helper threads' time is not the caller's CPU time);
// iteration_over_klu = (tangent assembly + refactor and solve) / (refactor and solve), the figure of
// merit; tangent_threads and residual_threads, the threads the assemblies took (1 where they do not pay).
inline void TimeIteration(benchmark::State& state, ModelSpec spec, int threads) {
  spec.solver.threads = threads;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  for (int k = 0; k < 20; ++k) simulation.TryStep(model.solver().dt);
  const StepContext& ctx = simulation.last_context();
  SparseSystem system(model);
  Eigen::VectorXd dx;
  // Outside the timing: the symbolic analysis and first factorisation, and the serial assemblies that decide
  // whether the threads pay.
  for (int k = 0; k < 4; ++k) {
    system.Assemble(ctx, true);
    system.Solve(&dx, true);
    system.Assemble(ctx, false);
  }
  int tangent_threads = 1, residual_threads = 1;
  using Clock = std::chrono::steady_clock;
  double tangent = 0, residual = 0, klu = 0;
  // The fastest of each: on a machine shared with other work, the iterations in which both threads had a core.
  double tangent_min = 1e9, residual_min = 1e9, klu_min = 1e9;
  long count = 0;
  for (auto _ : state) {
    auto t0 = Clock::now();
    system.Assemble(ctx, true);
    auto t1 = Clock::now();
    tangent_threads = system.assembly_threads();
    if (!system.Solve(&dx, true)) state.SkipWithError("singular");
    auto t2 = Clock::now();
    system.Assemble(ctx, false);
    auto t3 = Clock::now();
    residual_threads = system.assembly_threads();
    const double t_tangent = std::chrono::duration<double>(t1 - t0).count();
    const double t_klu = std::chrono::duration<double>(t2 - t1).count();
    const double t_residual = std::chrono::duration<double>(t3 - t2).count();
    tangent += t_tangent;
    klu += t_klu;
    residual += t_residual;
    tangent_min = std::min(tangent_min, t_tangent);
    klu_min = std::min(klu_min, t_klu);
    residual_min = std::min(residual_min, t_residual);
    ++count;
  }
  state.counters["tangent_assembly_us"] = 1e6 * tangent / count;
  state.counters["residual_assembly_us"] = 1e6 * residual / count;
  state.counters["klu_refactor_solve_us"] = 1e6 * klu / count;
  state.counters["tangent_assembly_min_us"] = 1e6 * tangent_min;
  state.counters["residual_assembly_min_us"] = 1e6 * residual_min;
  state.counters["klu_refactor_solve_min_us"] = 1e6 * klu_min;
  state.counters["iteration_over_klu"] = (tangent + klu) / klu;
  state.counters["unknowns"] = model.num_unknowns();
  state.counters["tangent_threads"] = tangent_threads;
  state.counters["residual_threads"] = residual_threads;
}

}  // namespace bench
}  // namespace flexmbd
