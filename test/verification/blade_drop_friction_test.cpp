// The blade drop case with Coulomb friction in its hinge (test/data/yaml/blade_drop_hinge_friction.yaml), run
// from its files at their settings: released from its held static shape, the root breaks away at once (19 N m of
// gravity against a slip torque of about 0.1 N m). It used to stall at t = 0.01 s: the breakaway ended the
// starting-step trials and left the first step, the default 0.01 s, untested (docs/theory.md, "First step").

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "../integration/helpers/csv_table.hpp"
#include "csv_books.hpp"
#include "friction_bound.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace blade_drop_friction_test {

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
  // after it, which keep the step below a tenth of the default 0.01 s (measured: 1.74e-4 s; 1.32e-4 s before (T12b)).
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

// On fixed steps of 0.01 s (test/data/yaml/blade_drop_hinge_friction_fixed_step.yaml, a fuzzing finding) the
// release is unresolved: the first step leaves the root at the end rate of a bending mode (-3.7 rad/s, the mean
// rate -2.6). The run stopped at t = 0.01 s below dt_min, a capture judged on that end rate undone by ever shorter
// steps (docs/theory.md (F4)). Through the runner at the file's settings it completes; the hinge angle at 0.5 s is
// compared with a run on fixed steps of 1e-3 s.
TEST(BladeDropFriction, FixedStepsOfTenMillisecondsFollowTheFineSteps) {
  std::ifstream file(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/yaml/blade_drop_hinge_friction_fixed_step.yaml");
  std::stringstream text;
  text << file.rdbuf();
  const std::string coarse_yaml = text.str();
  auto run = [](std::string yaml, const std::string& name) {
    const std::string csv = testing::TempDir() + name + ".csv";
    const std::string output = "output:\n";
    yaml.insert(yaml.find(output) + output.size(), "  csv: " + csv + "\n");
    const std::string out = test::RunnerOutput("config/blade_drop/blade_drop.urdf", yaml, name);
    EXPECT_NE(out.find("finished at t = 0.5 s"), std::string::npos) << out;
    return test::ReadCsv(csv);
  };
  std::string fine_yaml = coarse_yaml;
  const std::string step = "dt: 0.01,";
  ASSERT_NE(fine_yaml.find(step), std::string::npos) << fine_yaml;
  fine_yaml.replace(fine_yaml.find(step), step.size(), "dt: 1.0e-3,");
  const test::CsvTable coarse = run(coarse_yaml, "friction_release_coarse");
  const test::CsvTable fine = run(fine_yaml, "friction_release_fine");
  ASSERT_FALSE(coarse.rows.empty());
  ASSERT_FALSE(fine.rows.empty());
  const size_t angle = coarse.Column("joint.hinge.position");
  RecordProperty("angle_coarse_rad", std::to_string(coarse.rows.back().at(angle)));
  RecordProperty("angle_fine_rad", std::to_string(fine.rows.back().at(angle)));
  // The scheme is of second order: its error C h^2, with C from the runs at 1e-3 and 2e-4 s (3.2e-4 rad apart at
  // 0.5 s, so C = 330 rad/s^2), is 0.033 rad at 0.01 s (measured 0.0122 rad from the 1e-3 s run, 1.6%).
  constexpr double kAngleTolerance = 0.033;
  EXPECT_NEAR(coarse.rows.back().at(angle), fine.rows.back().at(angle), kAngleTolerance);
  for (const test::CsvTable* table : {&coarse, &fine}) {
    for (const std::vector<double>& row : table->rows) {
      // The books (T6): energy now plus everything removed equals the energy at release, to Newton's tolerance
      // (solver.tol, 1e-6 by default) times the energy through them (as EnergyBooksBalanceWithFrictionWork;
      // measured 3.7e-8).
      auto at = [&](const char* column) { return row.at(table->Column(column)); };
      const test::CsvBooks books = test::BooksAt(*table, row);
      EXPECT_NEAR(books.imbalance, 0.0, 1e-6 * books.throughput) << "t = " << at("t");
      // The hinge holds the blade's root at its axis: the root's displacement is the constraint residual.
      const double root = std::hypot(at("beam.blade.s0.ux"), at("beam.blade.s0.uy"), at("beam.blade.s0.uz"));
      EXPECT_LT(root, 1e-12) << "t = " << at("t");
    }
  }
}

}  // namespace blade_drop_friction_test
}  // namespace flexmbd
