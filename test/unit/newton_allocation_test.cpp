// No heap allocation in the Newton loop (issue 12): after a warm-up iteration, assembling residual and tangent,
// refactorising and solving allocate nothing, for a model with beams, joints,
// springs, dampers, elastic stops and Coulomb friction, and for a rotor whose blades' strips share its inflow. Counted
// by interposing malloc for the whole process (libstdc++'s operator new and Eigen's dynamic storage both end in
// malloc).

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "stepped_model.hpp"

extern "C" void* __libc_malloc(size_t size);

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

// Out of line, so that a debugger can stop on a counted allocation (break CountAllocation).
__attribute__((noinline)) void CountAllocation() { g_allocations.fetch_add(1, std::memory_order_relaxed); }

// AddressSanitizer owns malloc: an interposed one is called before the sanitizer is set up and crashes every test
// of the process at start, so a sanitizer build (-DFLEXMBD_SANITIZE=ON) leaves malloc alone and skips the count.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kCountsAllocations = false;
#else
constexpr bool kCountsAllocations = true;
extern "C" void* malloc(size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) CountAllocation();
  return __libc_malloc(size);
}
#endif

namespace flexmbd {
namespace newton_allocation_test {

ModelSpec Load(const std::string& urdf, const std::string& yaml) {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/";
  return LoadModelSpec(dir + urdf, dir + yaml);
}

// Allocations made by one Newton iteration (assembly with and without the tangent, refactorisation and
// solve) at the last iteration of the model's `steps`-th step, with the elements evaluated on `threads` threads.
// `tangent_threads`: the threads the counted tangent assembly took.
long AllocationsPerIteration(ModelSpec spec, int steps, int threads, int* tangent_threads = nullptr) {
  spec.solver.threads = threads;
  test::SteppedModel stepped(spec, steps);
  const StepContext& ctx = stepped.ctx();
  SparseSystem& system = stepped.system;
  Eigen::VectorXd dx(stepped.model.num_unknowns());
  long allocations = 0;
  // The first passes warm up: symbolic analysis, first factorisation, the timed serial assemblies that decide
  // whether threads pay, and the helpers' start.
  constexpr int kWarmUpPasses = 4;
  for (int pass = 0; pass <= kWarmUpPasses; ++pass) {
    g_allocations = 0;
    g_counting = pass == kWarmUpPasses;
    system.Assemble(ctx, true);
    if (tangent_threads != nullptr) *tangent_threads = system.assembly_threads();
    const bool solved = system.Solve(&dx, true);
    system.Assemble(ctx, false);
    g_counting = false;
    EXPECT_TRUE(solved);
    allocations = g_allocations;
  }
  return allocations;
}

TEST(NewtonIteration, FlexibleAntennaWithFrictionAndStopsAllocatesNothing) {
  if (!kCountsAllocations) GTEST_SKIP() << "malloc is AddressSanitizer's in this build";
  const ModelSpec spec = Load("config/antenna/antenna.urdf", "test/data/yaml/antenna_flexible_friction.yaml");
  EXPECT_EQ(AllocationsPerIteration(spec, 5, 1), 0);
}

// The same with the elements on two threads (src/core/solver/parallel_assembly.hpp): handing them over allocates
// nothing either. The tangent assembly (about 200 us) is far above the break-even, so it takes both threads.
TEST(NewtonIteration, TwoThreadsAllocateNothing) {
  if (!kCountsAllocations) GTEST_SKIP() << "malloc is AddressSanitizer's in this build";
  const ModelSpec spec = Load("config/antenna/antenna.urdf", "test/data/yaml/antenna_flexible_friction.yaml");
  int tangent_threads = 0;
  EXPECT_EQ(AllocationsPerIteration(spec, 5, 2, &tangent_threads), 0);
  EXPECT_EQ(tangent_threads, 2);
}

// The stiff two-bladed hover rotor (test/data/yaml/hover_rotor.yaml) with either inflow: the rotor's element
// evaluates its one or three states (docs/theory.md, (A13), (A14)), each blade's strips read them and add to their
// rows.
TEST(NewtonIteration, RotorWithUniformOrHarmonicInflowAllocatesNothing) {
  if (!kCountsAllocations) GTEST_SKIP() << "malloc is AddressSanitizer's in this build";
  ModelSpec spec = Load("test/data/urdf/hover_rotor.urdf", "test/data/yaml/hover_rotor.yaml");
  for (const AeroRotorSpec::Inflow inflow : {AeroRotorSpec::Inflow::kUniform, AeroRotorSpec::Inflow::kHarmonic}) {
    spec.aero_rotors.at(0).inflow = inflow;
    EXPECT_EQ(AllocationsPerIteration(spec, 5, 2), 0)
        << (inflow == AeroRotorSpec::Inflow::kHarmonic ? "harmonic" : "uniform");
  }
}

}  // namespace newton_allocation_test
}  // namespace flexmbd
