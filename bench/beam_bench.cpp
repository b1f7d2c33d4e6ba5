// Cost per time step of a cantilever of N cubic beam elements under gravity (clamped at the root, energy-
// decaying scheme, fixed step), split into assembly, factorisation and solve. It should grow about linearly
// with N. Run: beam_bench [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include "step_bench.hpp"

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace {

flexmbd::ModelSpec Cantilever(int elements) {
  flexmbd::ModelSpec spec;
  spec.source = "cantilever (bench)";
  flexmbd::BeamSpec beam;
  beam.name = "beam";
  beam.length = 2.0;
  beam.elements = elements;
  beam.order = 3;
  beam.section.stiffness.diagonal() << 1.0e7, 4.0e6, 4.0e6, 50.0, 100.0, 100.0;
  beam.section.mass_per_length = 1.0;
  beam.section.inertia_per_length = flexmbd::Vec3(1e-3, 5e-4, 5e-4);
  spec.beams.push_back(beam);
  flexmbd::JointSpec clamp;
  clamp.name = "clamp";
  clamp.type = flexmbd::JointType::kFixed;
  clamp.child = "beam";
  spec.joints.push_back(clamp);
  spec.solver.adaptive = false;
  spec.solver.dt = 1.0e-3;
  spec.solver.tol = 1.0e-6;
  spec.output.rate_hz = 0;
  return spec;
}

void BM_CantileverStep(benchmark::State& state) {
  flexmbd::bench::TimeSteps(state, Cantilever(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_CantileverStep)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
