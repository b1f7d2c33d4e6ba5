// Elements evaluated on several threads (src/core/solver/parallel_assembly.hpp) give the assembly of one thread
// bit for bit: residual, row magnitudes, row sums of the tangent and the solution of the factorised system, for a
// cantilever of many beam elements and the flexible antenna with friction and stops (beams, joints, springs,
// dampers, stops and friction in one model). Reference: the same SparseSystem with solver.threads 1 (the serial
// loop). Tolerance: none, since the same sums are made in the same order.

#include <gtest/gtest.h>

#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "../verification/beam_cases.hpp"
#include "stepped_model.hpp"

namespace flexmbd {
namespace parallel_assembly_test {

struct Assembled {
  Eigen::VectorXd residual, magnitude, row_abs_sum, dx, residual_alone, magnitude_alone;
  int tangent_threads = 0, residual_threads = 0;
};

// Assemblies and a solve of one SparseSystem on `threads` threads at the last iteration of the spec's `steps`-th
// step, after the passes that decide whether the threads pay.
Assembled AssembleOn(ModelSpec spec, int steps, int threads) {
  spec.solver.threads = threads;
  test::SteppedModel stepped(spec, steps);
  const StepContext& ctx = stepped.ctx();
  SparseSystem& system = stepped.system;
  Assembled a;
  for (int pass = 0; pass < 5; ++pass) {
    system.Assemble(ctx, true);
    a.residual = system.residual();
    a.magnitude = system.magnitude();
    a.row_abs_sum = system.row_abs_sum();
    a.tangent_threads = system.assembly_threads();
    EXPECT_TRUE(system.Solve(&a.dx, true));
    system.Assemble(ctx, false);
    a.residual_alone = system.residual();
    a.magnitude_alone = system.magnitude();
    a.residual_threads = system.assembly_threads();
  }
  return a;
}

void ExpectBitForBit(const ModelSpec& spec, int steps, bool residual_on_threads) {
  const Assembled one = AssembleOn(spec, steps, 1);
  const Assembled two = AssembleOn(spec, steps, 2);
  EXPECT_EQ(one.tangent_threads, 1);
  EXPECT_EQ(two.tangent_threads, 2);
  if (residual_on_threads) {
    EXPECT_EQ(two.residual_threads, 2);
  }
  EXPECT_TRUE(one.residual == two.residual);
  EXPECT_TRUE(one.magnitude == two.magnitude);
  EXPECT_TRUE(one.row_abs_sum == two.row_abs_sum);
  EXPECT_TRUE(one.dx == two.dx);
  EXPECT_TRUE(one.residual_alone == two.residual_alone);
  EXPECT_TRUE(one.magnitude_alone == two.magnitude_alone);
}

// A clamped cantilever of 200 cubic elements sagging under gravity: about 1 ms to assemble with the tangent and
// 0.3 ms without, far above the break-even of the threads.
TEST(ParallelAssembly, TwoThreadsAssembleACantileverAsOneBitForBit) {
  ModelSpec spec = test::Cantilever(2.0, 200, 3, test::Section(1.0e7, 4.0e6, 50.0, 100.0, 1.0, 1.0e-3, 5.0e-4));
  spec.solver.gravity = Vec3(0.0, 0.0, -9.81);
  spec.solver.adaptive = false;
  spec.solver.dt = 1.0e-3;
  ExpectBitForBit(spec, 3, true);
}

TEST(ParallelAssembly, TwoThreadsAssembleTheFlexibleAntennaAsOneBitForBit) {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/";
  // Its residual alone (about 40 us) may stay on one thread on a fast machine; its tangent (about 200 us) does not.
  ExpectBitForBit(
      LoadModelSpec(dir + "config/antenna/antenna.urdf", dir + "test/data/yaml/antenna_flexible_friction.yaml"), 5,
      false);
}

}  // namespace parallel_assembly_test
}  // namespace flexmbd
