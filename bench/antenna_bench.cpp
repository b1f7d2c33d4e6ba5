// The space antenna reference case (config/antenna/, docs/cases.md) run to t_end = 200 s with adaptive steps:
// the time of a whole run and its steps, for the viscous-damper variant (target: <= 2,000 steps, <= 0.3 s) and
// the friction variant (target: <= 20,000 steps, <= 2 s). Loading is outside the timed loop; output samples go
// to a sink that drops them.

#include <benchmark/benchmark.h>

#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "step_bench.hpp"

namespace flexmbd {
namespace {

void AntennaRun(benchmark::State& state, const std::string& variant) {
  const std::string dir = std::string(FLEXMBD_BENCH_SOURCE_DIR) + "/config/antenna/";
  const Model model = BuildModel(LoadModelSpec(dir + "antenna.urdf", dir + "antenna_" + variant + ".yaml"));
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

BENCHMARK_CAPTURE(AntennaRun, dampers, std::string("dampers"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(AntennaRun, friction, std::string("friction"))->Unit(benchmark::kMillisecond);

// The flexible antenna (bench/antenna_flexible/, panels of cubic beams): the cost of one Newton iteration beside
// one KLU refactorisation and solve of the same matrix (target: at most 0.1 ms and 3x).
void FlexibleAntennaIteration(benchmark::State& state) {
  const std::string source = std::string(FLEXMBD_BENCH_SOURCE_DIR);
  bench::TimeIteration(state, LoadModelSpec(source + "/config/antenna/antenna.urdf",
                                            source + "/bench/antenna_flexible/antenna_flexible.yaml"));
}
BENCHMARK(FlexibleAntennaIteration)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace flexmbd

BENCHMARK_MAIN();
