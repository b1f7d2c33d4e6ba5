// No heap allocation in the Newton loop (issue 12): after a warm-up iteration, building the step's context,
// assembling residual and tangent, refactorising and solving allocate nothing, for a model with beams, joints,
// springs, dampers, elastic stops and Coulomb friction. Counted by interposing malloc for the whole process
// (libstdc++'s operator new and Eigen's dynamic storage both end in malloc).

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

extern "C" void* __libc_malloc(size_t size);

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

// Out of line, so that a debugger can stop on a counted allocation (break CountAllocation).
__attribute__((noinline)) void CountAllocation() { g_allocations.fetch_add(1, std::memory_order_relaxed); }

extern "C" void* malloc(size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) CountAllocation();
  return __libc_malloc(size);
}

namespace flexmbd {
namespace {

// Allocations made by one Newton iteration of a dynamic step of the model from its state after `steps` steps.
long AllocationsPerIteration(const std::string& urdf, const std::string& yaml, int steps) {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/";
  const Model model = BuildModel(LoadModelSpec(dir + urdf, dir + yaml));
  Simulation simulation(model);
  const double h = model.solver().dt;
  for (int k = 0; k < steps; ++k) simulation.TryStep(h);
  const State start = simulation.state();
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model.num_unknowns());
  for (int k = 0; k < model.num_nodes(); ++k) {
    unknowns.segment<3>(6 * k) = h * start.nodes[k].v;
    unknowns.segment<3>(6 * k + 3) = h * start.nodes[k].w;
  }
  StepContextBuilder builder(model);
  const std::vector<NodeSchemeCoefficients> coefficients(model.num_nodes());
  SparseSystem system(model);
  Eigen::VectorXd dx(model.num_unknowns());
  long allocations = 0;
  for (int pass = 0; pass < 2; ++pass) {  // the first pass warms up (symbolic analysis, first factorisation)
    g_allocations = 0;
    g_counting = pass == 1;
    const StepContext& ctx = builder.Dynamic(start, unknowns, h, coefficients);
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
  EXPECT_EQ(AllocationsPerIteration("config/antenna/antenna.urdf", "test/data/yaml/antenna_flexible_friction.yaml", 5),
            0);
}

}  // namespace
}  // namespace flexmbd
