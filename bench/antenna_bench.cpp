// The space antenna reference case (config/antenna/, docs/cases.md) run to t_end = 200 s with adaptive steps:
// the time of a whole run and its steps, for the viscous-damper variant (target: <= 2,000 steps, <= 0.3 s) and
// the friction variant (target: <= 20,000 steps, <= 2 s); and the flexible antenna (bench/antenna_flexible/),
// its whole run and one Newton iteration; one Newton iteration of the published antenna's case 1
// (config/antenna_published/, issue 16). Loading is outside the timed loop; output samples go to a sink that
// drops them.

#include <benchmark/benchmark.h>

#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "step_bench.hpp"

namespace flexmbd {
namespace {

// Runs `spec` to its t_end once per benchmark iteration; counters: the last run's steps and iterations.
void TimeRun(benchmark::State& state, const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  StepStatistics last;
  for (auto _ : state) {
    Simulation simulation(model);
    simulation.Run([](const OutputSample&) {});
    last = simulation.statistics();
  }
  state.counters["steps_accepted"] = last.accepted;
  state.counters["steps_rejected"] = last.rejected();
  state.counters["newton_iterations"] = last.newton_iterations;
  state.counters["unknowns"] = model.num_unknowns();
}

void AntennaRun(benchmark::State& state, const std::string& variant) {
  const std::string dir = std::string(FLEXMBD_BENCH_SOURCE_DIR) + "/config/antenna/";
  TimeRun(state, LoadModelSpec(dir + "antenna.urdf", dir + "antenna_" + variant + ".yaml"));
}

BENCHMARK_CAPTURE(AntennaRun, dampers, std::string("dampers"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(AntennaRun, friction, std::string("friction"))->Unit(benchmark::kMillisecond);

ModelSpec FlexibleAntenna() {
  const std::string source = std::string(FLEXMBD_BENCH_SOURCE_DIR);
  return LoadModelSpec(source + "/config/antenna/antenna.urdf",
                       source + "/bench/antenna_flexible/antenna_flexible.yaml");
}

// The flexible antenna's whole 200 s with the default adaptive steps (error_tol 1e-4) instead of the model's fixed
// 0.05 s (the target: 2,000 steps and 0.3 s).
void FlexibleAntennaRun(benchmark::State& state) {
  ModelSpec spec = FlexibleAntenna();
  spec.solver.adaptive = true;
  spec.solver.error_tol = 1.0e-4;
  TimeRun(state, spec);
}
BENCHMARK(FlexibleAntennaRun)->Unit(benchmark::kMillisecond)->Iterations(1);

// The flexible antenna (bench/antenna_flexible/, panels of cubic beams): the cost of one Newton iteration beside
// one KLU refactorisation and solve of the same matrix (target: at most 0.1 ms and 3x).
void FlexibleAntennaIteration(benchmark::State& state) {
  bench::TimeIteration(state, FlexibleAntenna(), static_cast<int>(state.range(0)));
}
BENCHMARK(FlexibleAntennaIteration)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond)->UseRealTime();

// The published antenna's case 1 (config/antenna_published/case1.yaml: beams, friction): a fresh tangent and its
// factorisation, the cost every step of that case pays once, beside one KLU refactorisation and solve.
void PublishedAntennaIteration(benchmark::State& state) {
  const std::string dir = std::string(FLEXMBD_BENCH_SOURCE_DIR) + "/config/antenna_published/";
  bench::TimeIteration(state, LoadModelSpec(dir + "antenna_published.urdf", dir + "case1.yaml"),
                       static_cast<int>(state.range(0)));
}
BENCHMARK(PublishedAntennaIteration)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
}  // namespace flexmbd

BENCHMARK_MAIN();
