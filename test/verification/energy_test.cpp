// Energy behaviour of the time integration on a conservative double pendulum (docs/theory.md, (T6)).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "case_builders.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {
namespace energy_test {

// A large step for this pendulum (period ~2 s, chaotic motion): 100 steps per period of the linear mode.
constexpr double kLargeStep = 0.02;
constexpr int kSteps = 10000;

struct RunRecord {
  double first_energy = 0, max_relative_drift = 0, max_increase = 0, max_constraint = 0, final_energy = 0;
};

RunRecord RunDoublePendulum(SolverSpec::Integrator integrator) {
  ModelSpec spec = test::DoublePendulum(1.0, 0.5, 0.02);
  spec.solver.integrator = integrator;
  spec.solver.dt = kLargeStep;
  spec.solver.t_end = kSteps * kLargeStep;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  RunRecord record;
  bool first = true;
  double previous = 0;
  StepContextBuilder builder(model);
  simulation.Run([&](const OutputSample& s) {
    const double energy = s.total();
    if (first) {
      record.first_energy = previous = energy;
      first = false;
    }
    const double scale = std::abs(record.first_energy) + s.kinetic;
    record.max_relative_drift = std::max(record.max_relative_drift, std::abs(energy - record.first_energy) / scale);
    record.max_increase = std::max(record.max_increase, (energy - previous) / scale);
    previous = energy;
    const StepContext& ctx = builder.AtState(simulation.state());
    for (const Joint* joint : model.joints()) {
      record.max_constraint = std::max(record.max_constraint, joint->ConstraintValues(ctx).cwiseAbs().maxCoeff());
    }
  });
  record.final_energy = previous;
  // At this step the chaotic phases occasionally make Newton fail from the extrapolated predictor; the step is
  // then cut and retried. Such retries must stay rare.
  EXPECT_GE(simulation.statistics().accepted, kSteps);
  EXPECT_LT(simulation.statistics().rejected(), kSteps / 100);
  return record;
}

// Energy scale for the relative measures: |E0| + kinetic energy, both O(10 J) here.

TEST(EnergyPreservingScheme, DoublePendulumKeepsEnergy) {
  const RunRecord r = RunDoublePendulum(SolverSpec::Integrator::kEnergyPreserving);
  // The discrete energy identity is exact; what remains is the Newton tolerance (1e-12 relative per step)
  // accumulated over 1e4 steps, and round-off. The issue asks for 1e-8.
  constexpr double kEnergyTolerance = 1.0e-8;
  EXPECT_LT(r.max_relative_drift, kEnergyTolerance);
}

// The energy-decaying run is shared by the tests that check different properties of it.
const RunRecord& EnergyDecayingRun() {
  static const RunRecord record = RunDoublePendulum(SolverSpec::Integrator::kEnergyDecaying);
  return record;
}

TEST(EnergyDecayingScheme, DoublePendulumEnergyNeverIncreases) {
  const RunRecord& r = EnergyDecayingRun();
  // Each step changes energy by -D <= 0 exactly; a rise can only come from the Newton residual (1e-12
  // relative) and round-off, so anything above 1e-11 relative per step is a real increase.
  constexpr double kIncreaseTolerance = 1.0e-11;
  EXPECT_LT(r.max_increase, kIncreaseTolerance);
  EXPECT_LT(r.final_energy, r.first_energy);  // and it does dissipate on this chaotic motion at a large step
}

TEST(EnergyDecayingScheme, ConstraintsHoldAtEveryStep) {
  const RunRecord& r = EnergyDecayingRun();
  // Constraints are solved to kConstraintTolerance = 1e-11 at every step; the issue asks for 1e-10.
  constexpr double kConstraintLimit = 1.0e-10;
  EXPECT_LT(r.max_constraint, kConstraintLimit);
}

}  // namespace energy_test
}  // namespace flexmbd
