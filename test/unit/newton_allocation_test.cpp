// No heap allocation in the Newton loop (issue 12): after a warm-up iteration, assembling residual and tangent,
// refactorising and solving allocate nothing, for a model with beams, joints,
// springs, dampers, elastic stops and Coulomb friction, and for a rotor whose blades' strips share its inflow. Counted by interposing malloc for the whole process
// (libstdc++'s operator new and Eigen's dynamic storage both end in malloc).

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/sparse_system.hpp"

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
// solve) at the last iteration of the model's `steps`-th step.
long AllocationsPerIteration(const ModelSpec& spec, int steps) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  for (int k = 0; k < steps; ++k) simulation.TryStep(model.solver().dt);
  const StepContext& ctx = simulation.last_context();
  SparseSystem system(model);
  Eigen::VectorXd dx(model.num_unknowns());
  long allocations = 0;
  for (int pass = 0; pass < 2; ++pass) {  // the first pass warms up (symbolic analysis, first factorisation)
    g_allocations = 0;
    g_counting = pass == 1;
    system.Assemble(ctx, true);
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
  EXPECT_EQ(AllocationsPerIteration(Load("config/antenna/antenna.urdf", "test/data/yaml/antenna_flexible_friction.yaml"), 5),
            0);
}

// The stiff two-bladed hover rotor (test/data/yaml/hover_rotor.yaml) with either inflow: the rotor's element
// evaluates its one or three states (docs/theory.md, (A13), (A14)), each blade's strips read them and add to their
// rows.
TEST(NewtonIteration, RotorWithUniformOrHarmonicInflowAllocatesNothing) {
  if (!kCountsAllocations) GTEST_SKIP() << "malloc is AddressSanitizer's in this build";
  ModelSpec spec = Load("test/data/urdf/hover_rotor.urdf", "test/data/yaml/hover_rotor.yaml");
  for (const AeroRotorSpec::Inflow inflow : {AeroRotorSpec::Inflow::kUniform, AeroRotorSpec::Inflow::kHarmonic}) {
    spec.aero_rotors.at(0).inflow = inflow;
    EXPECT_EQ(AllocationsPerIteration(spec, 5), 0) << (inflow == AeroRotorSpec::Inflow::kHarmonic ? "harmonic" : "uniform");
  }
}

}  // namespace newton_allocation_test
}  // namespace flexmbd
