// The simulation loop: advancing in pieces (as the ROS node does between pauses) gives the same samples as one
// run, and samples come at the output rate whatever the step.

#include <gtest/gtest.h>

#include <vector>

#include "case_builders.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace simulation_test {

ModelSpec AdaptivePendulum() {
  ModelSpec spec = test::Pendulum(1.0, 1.0, 1.0e-3);
  spec.solver.adaptive = true;
  spec.solver.dt = 1.0e-3;
  spec.solver.t_end = 2.0;
  spec.output.rate_hz = 50;
  return spec;
}

TEST(Simulation, AdvancingInPiecesMatchesOneRun) {
  const Model model = BuildModel(AdaptivePendulum());
  std::vector<OutputSample> whole, pieces;
  Simulation one(model);
  one.Run([&](const OutputSample& s) { whole.push_back(s); });
  Simulation split(model);
  split.Begin([&](const OutputSample& s) { pieces.push_back(s); });
  for (double t = 0.37; t < 2.0; t += 0.37) {
    split.AdvanceTo(t, 2.0, [&](const OutputSample& s) { pieces.push_back(s); });
  }
  split.AdvanceTo(2.0, 2.0, [&](const OutputSample& s) { pieces.push_back(s); });
  ASSERT_EQ(whole.size(), pieces.size());
  for (size_t k = 0; k < whole.size(); ++k) {
    EXPECT_EQ(whole[k].t, pieces[k].t);
    EXPECT_EQ(whole[k].position[0], pieces[k].position[0]);  // the same steps, bit for bit
  }
}

TEST(Simulation, SamplesComeAtTheOutputRate) {
  const Model model = BuildModel(AdaptivePendulum());
  Simulation simulation(model);
  std::vector<double> times;
  simulation.Run([&](const OutputSample& s) { times.push_back(s.t); });
  ASSERT_EQ(times.size(), 101u);  // 0, 0.02, ..., 2.0
  // Sample times are t_start + k / rate up to the round-off of the sum.
  constexpr double kTimeTolerance = 1.0e-12;
  for (size_t k = 0; k < times.size(); ++k) EXPECT_NEAR(times[k], 0.02 * k, kTimeTolerance);
  EXPECT_LT(simulation.statistics().accepted, 1000);  // the steps are not tied to the samples
}

}  // namespace simulation_test
}  // namespace flexmbd
