// SolveNewton on a static pendulum held by a spring: the approximate solve (NewtonOptions::increment_test_only)
// stops at the first trusted increment below the tolerance, before the full test would, and its iterate lies
// within that tolerance of the converged one; a simplified iteration whose contraction is measured stops when the
// error it leaves, not its increment, is below the tolerance; an approximate solve may take its first increment on
// the rate an earlier one measured.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/newton.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "tangent_test_models.hpp"

namespace flexmbd {
namespace newton_test {

// The pivoted arm (0.6 m) held by a torsional spring: it settles where the spring balances gravity, about half
// a radian down (a nonlinear root: the moment arm is 0.6 cos q).
Model SprungPendulum() {
  ModelSpec spec = test::PivotedArm("sprung pendulum (unit test)");
  spec.joints[0].effects[0].springs.push_back(SpringSpec{20.0, 0.0});
  return BuildModel(spec);
}

struct Solved {
  NewtonReport report;
  double angle = 0;           // [rad]
  double last_increment = 0;  // largest kinematic entry of the last increment [rad]
  double travelled = 0;       // largest increment, against which the tolerance judges them [rad]
};

// Without the geometric stiffness (gravity's moment changing with the angle) the tangent is inexact and the
// iteration contracts linearly, as a step's simplified iteration does.
Solved SolveStatic(const Model& model, double tol, const NewtonOptions& options, bool geometric_stiffness = true) {
  SparseSystem system(model);
  StepContextBuilder builder(model);
  builder.set_geometric_stiffness(geometric_stiffness);
  State state = model.initial_state();
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model.num_unknowns());
  double travelled = 0;
  const int n_kinematic = model.num_unknowns() - model.num_multipliers();
  Solved solved;
  solved.report = SolveNewton(
      model, &system, tol, 50, RoundOffFloor(model.length_scale()),
      [&](int, bool) -> const StepContext& {
        unknowns.setZero();
        unknowns.tail(model.num_multipliers()) = state.lambda;
        return builder.Static(state, unknowns, 0.0, 1.0);
      },
      [&](const Eigen::VectorXd& increment) {
        for (int k = 0; k < model.num_nodes(); ++k) {
          state.nodes[k].x += increment.segment<3>(model.node_unknown(k));
          state.nodes[k].R = state.nodes[k].R * Exp(increment.segment<3>(model.node_unknown(k) + 3));
        }
        for (int k = 0; k < model.num_variables(); ++k) state.q[k] += increment[model.variable_unknown(k)];
        state.lambda += increment.tail(model.num_multipliers());
        solved.last_increment = increment.head(n_kinematic).cwiseAbs().maxCoeff();
        travelled = std::max(travelled, solved.last_increment);
        return travelled + kMotionFloor;
      },
      options);
  solved.angle = state.q[0];
  solved.travelled = travelled;
  return solved;
}

TEST(Newton, AnApproximateSolveStopsAtItsFirstSmallIncrement) {
  const Model model = SprungPendulum();
  constexpr double kLoose = 1.0e-3;
  const Solved reference = SolveStatic(model, 1.0e-12, NewtonOptions{});
  const Solved full = SolveStatic(model, kLoose, NewtonOptions{});
  const Solved approximate = SolveStatic(model, kLoose, NewtonOptions{false, true});
  ASSERT_TRUE(reference.report.converged && full.report.converged && approximate.report.converged);
  // The pendulum moves by about half a radian: not a root the first iterate finds.
  EXPECT_GT(std::abs(reference.angle), 0.3);
  // The full test also asks that the residual the last increment came from be small against the forces; the
  // approximate solve stops as soon as the increment is (5 iterations against 8 here).
  EXPECT_LT(approximate.report.iterations, full.report.iterations);
  // Its iterate is within the tolerance of the travel (about 0.5 rad) of the root: the remaining error is the
  // next increment, below the last one (it contracts).
  EXPECT_LT(std::abs(approximate.angle - reference.angle), kLoose * 0.5);
}

TEST(Newton, AContractingIterationStopsWhenTheErrorItLeavesIsSmall) {
  const Model model = SprungPendulum();
  // The increments shrink by 0.29 per iteration here (0.59, 0.10, ..., 1.4e-6, 4.1e-7, 1.2e-7 rad).
  constexpr double kTol = 1.0e-7;
  const Solved reference = SolveStatic(model, 1.0e-12, NewtonOptions{});
  const Solved simplified = SolveStatic(model, kTol, NewtonOptions{}, false);
  ASSERT_TRUE(reference.report.converged && simplified.report.converged);
  const double target = kTol * (simplified.travelled + kMotionFloor);
  // It stopped on the contraction: its last increment was still above the target ...
  EXPECT_GT(simplified.last_increment, target);
  // ... and the error it left, about theta / (1 - theta) of that increment, is below it (the iteration contracts
  // linearly, so the estimate is close; a factor 2 leaves room for the rate changing along the way).
  EXPECT_LT(std::abs(simplified.angle - reference.angle), 2.0 * target);
}

TEST(Newton, AnApproximateSolveTakesItsFirstIncrementOnAnExpectedContraction) {
  const Model model = SprungPendulum();
  constexpr double kLoose = 1.0e-3;
  NewtonOptions approximate{false, true};
  const Solved measuring = SolveStatic(model, kLoose, approximate);
  ASSERT_TRUE(measuring.report.converged);
  EXPECT_GT(measuring.report.iterations, 1);
  // The rate its iterations measured is reported for the next solve of its kind.
  EXPECT_TRUE(std::isfinite(measuring.report.contraction_factor));
  // Told to expect an iteration that converges at once, the approximate solve stops at its first increment ...
  approximate.expected_contraction_factor = 0.0;
  EXPECT_EQ(SolveStatic(model, kLoose, approximate).report.iterations, 1);
  // ... a full solve does not take the expectation: it tests its residual and its own contraction.
  NewtonOptions full;
  full.expected_contraction_factor = 0.0;
  EXPECT_EQ(SolveStatic(model, kLoose, full).report.iterations,
            SolveStatic(model, kLoose, NewtonOptions{}).report.iterations);
}

}  // namespace newton_test
}  // namespace flexmbd
