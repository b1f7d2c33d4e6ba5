// Cost per time step of an N-link pendulum chain (links along x at q = 0, hinges about y, gravity -z),
// split into assembly, factorisation and solve. Run: pendulum_chain_bench [--benchmark_filter=...]

#include <benchmark/benchmark.h>

#include "step_bench.hpp"

#include <string>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace {

using flexmbd::Vec3;

flexmbd::ModelSpec Chain(int links) {
  constexpr double kLength = 0.2, kMass = 0.5;  // [m], [kg] per link
  flexmbd::ModelSpec spec;
  spec.source = "pendulum chain (bench)";
  for (int k = 0; k < links; ++k) {
    flexmbd::BodySpec body;
    body.name = "link" + std::to_string(k);
    body.mass = kMass;
    body.inertia_cm_B = kMass * kLength * kLength / 12.0 * flexmbd::Mat3::Identity();
    body.p_BoBcm_B = Vec3(kLength / 2, 0, 0);
    body.p_WB = Vec3(k * kLength, 0, 0);
    spec.bodies.push_back(body);
    flexmbd::JointSpec joint;
    joint.name = "hinge" + std::to_string(k);
    joint.parent = k == 0 ? "" : "link" + std::to_string(k - 1);
    joint.child = body.name;
    joint.p_PJ = k == 0 ? Vec3::Zero() : Vec3(kLength, 0, 0);
    joint.axis_J = Vec3::UnitY();
    spec.joints.push_back(joint);
  }
  spec.solver.adaptive = false;
  spec.solver.dt = 1.0e-3;
  spec.solver.tol = 1.0e-6;
  spec.output.rate_hz = 0;
  return spec;
}

void BM_PendulumChainStep(benchmark::State& state) {
  flexmbd::bench::TimeSteps(state, Chain(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_PendulumChainStep)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
