// Cost per time step of a cantilever of N cubic beam elements under gravity (clamped at the root, energy-
// decaying scheme, fixed step), split into assembly, factorisation and solve. It should grow about linearly
// with N. Run: beam_bench [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include "step_bench.hpp"

#include "flexmbd/elements/beam_element.hpp"

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

void BM_CantileverIteration(benchmark::State& state) {
  flexmbd::bench::TimeIteration(state, Cantilever(static_cast<int>(state.range(0))), static_cast<int>(state.range(1)));
}
BENCHMARK(BM_CantileverIteration)
    ->ArgNames({"elements", "threads"})
    ->ArgsProduct({{1, 2, 4, 8, 10, 16, 100, 1000, 10000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One cubic element of a cantilever bent by a tip load, evaluated alone in a dynamic step (increments of a
// swinging motion): the element's own cost, residual alone and with its tangent.
void BM_CubicElement(benchmark::State& state) {
  const bool tangent = state.range(0) != 0;
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  C.diagonal() << 1.0e7, 4.0e6, 4.0e6, 50.0, 100.0, 100.0;
  const flexmbd::BeamElement element("e", {0, 1, 2, 3}, 0.2, C, state.range(1) != 0 ? 1.0e-3 : 0.0);
  std::vector<flexmbd::NodeStep> steps;
  for (int k = 0; k < 4; ++k) {
    flexmbd::NodeState n;
    const double s = 0.2 * k / 3;
    n.x = flexmbd::Vec3(s, 0.0, -0.05 * s * s);
    n.R = flexmbd::Exp(flexmbd::Vec3(0.0, 0.1 * s, 0.0));
    flexmbd::Vec6 increment;
    increment << 1e-4 * s, 0.0, -1e-3 * s, 0.0, 2e-3 * s, 1e-4;
    steps.push_back(flexmbd::MakeNodeStep(n, increment, flexmbd::AnalysisMode::kDynamic));
  }
  flexmbd::StepContext ctx;
  ctx.h = 1e-3;
  ctx.nodes = &steps;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(24), m = Eigen::VectorXd::Zero(24);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(24, 24);
  Eigen::Ref<Eigen::MatrixXd> J_ref(J);
  for (auto _ : state) {
    element.AddResidualAndTangent(ctx, r, m, tangent ? &J_ref : nullptr);
    benchmark::DoNotOptimize(r.data());
    benchmark::DoNotOptimize(J.data());
  }
}
BENCHMARK(BM_CubicElement)->ArgNames({"tangent", "damped"})->Args({0, 0})->Args({1, 0})->Args({0, 1})->Args({1, 1})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
