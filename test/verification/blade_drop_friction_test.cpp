// The blade drop case with Coulomb friction in its hinge (test/data/yaml/blade_drop_hinge_friction.yaml), run
// from its files at their settings: released from its held static shape, the root breaks away at once (19 N m of
// gravity against a slip torque of about 0.1 N m). It used to stall at t = 0.01 s: the breakaway ended the
// starting-step trials and left the first step, the default 0.01 s, untested (docs/theory.md, "First step").

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "friction_bound.hpp"

namespace flexmbd {
namespace {

struct FrictionDrop {
  FrictionDrop()
      : spec(LoadModelSpec(std::string(FLEXMBD_SOURCE_DIR) + "/config/blade_drop/blade_drop.urdf",
                           std::string(FLEXMBD_SOURCE_DIR) + "/test/data/yaml/blade_drop_hinge_friction.yaml")),
        model(BuildModel(spec)),
        simulation(model) {
    simulation.Run([this](const OutputSample& s) { samples.push_back(s); });
  }
  ModelSpec spec;
  Model model;
  Simulation simulation;
  std::vector<OutputSample> samples;
};

const FrictionDrop& Drop() {
  static const FrictionDrop drop;
  return drop;
}

TEST(BladeDropFriction, TheTrialStepsMeasureTheMotionAfterTheBreakaway) {
  const FrictionDrop& drop = Drop();
  ASSERT_NEAR(drop.samples.back().t, drop.spec.solver.t_end, 1e-12);
  // The root unbends at up to 3.7 rad/s from the release; the trials resolve the breakaway and measure the steps
  // after it, which keep the step below a tenth of the default 0.01 s (measured: 6.25e-4 s).
  const StepStatistics& stats = drop.simulation.statistics();
  RecordProperty("first_step_s", std::to_string(stats.h_start));
  EXPECT_LT(stats.h_start, drop.spec.solver.dt / 10);
  EXPECT_FALSE(drop.samples.at(1).friction.at(0).sticking);  // broken away from the first sample on
}

// Coulomb's law on every sample: sliding, |T| = mu_k rho N to round-off of the output (the torque is the law's
// value at the sample's slip direction); sticking, within mu_s rho N.
TEST(BladeDropFriction, CoulombLawHoldsWithTheNormalForceFromTheReaction) {
  const FrictionDrop& drop = Drop();
  const FrictionSpec& law = drop.spec.joints.at(0).effects.at(0).frictions.at(0);
  int sliding = 0;
  for (const OutputSample& s : drop.samples) {
    const FrictionSample& f = s.friction.at(0);
    EXPECT_GE(f.normal_force, law.preload) << "t = " << s.t;
    EXPECT_LE(test::StaticBoundRatio(drop.spec, drop.model, s), 1.0 + 1e-9) << "t = " << s.t;
    if (f.sticking || s.t == 0.0) continue;
    ++sliding;
    EXPECT_NEAR(std::abs(f.torque), law.mu_k * law.radius * f.normal_force, 1e-9 * law.radius * f.normal_force)
        << "t = " << s.t;
  }
  EXPECT_GT(sliding, static_cast<int>(drop.samples.size()) / 2);
}

// The books (docs/theory.md (T6)) with friction's work among the dissipated: energy now plus everything removed
// equals the energy at release, to Newton's tolerance times the energy through the books (as BladeDrop).
TEST(BladeDropFriction, EnergyBooksBalanceWithFrictionWork) {
  const FrictionDrop& drop = Drop();
  const OutputSample& f = drop.samples.front();
  const OutputSample& l = drop.samples.back();
  const double books = l.total() + l.dissipated + l.numerical_dissipation - l.external_work - f.total();
  const double throughput = std::abs(f.total()) + l.dissipated + l.numerical_dissipation + std::abs(l.external_work);
  EXPECT_NEAR(books, 0.0, drop.spec.solver.tol * throughput);
  EXPECT_GT(l.friction.at(0).work, 0.0);
  EXPECT_LE(l.friction.at(0).work, l.dissipated);
}

// On fixed steps of the default 0.01 s the release is unresolved (test/fuzz/solver_findings/
// fixed_step_friction_release.yaml, open): the run either completes or says to shrink the fixed step, never only
// to lower dt_min.
TEST(BladeDropFriction, FixedStepsTooLargeForTheReleaseAreNamedInTheFailure) {
  ModelSpec spec = Drop().spec;
  spec.solver.adaptive = false;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  try {
    simulation.Run([](const OutputSample&) {});
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("try a smaller solver.dt (fixed steps"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace flexmbd
