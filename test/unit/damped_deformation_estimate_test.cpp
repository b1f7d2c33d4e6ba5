// The local error estimate on a damped beam (docs/theory.md (T12b)): the third derivative of the beam's rigid
// motion counts in full, and that of its deformation relative to the rigid motion is divided by the deformation's
// decay over the time left, mu omega^2 (t_end - t) / 2, with omega^2 = |x'''| / |x'| of one mode. Checked on the
// flexible arm of test/data with prescribed node motions booked as accepted steps.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/math/so3.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {
namespace damped_deformation_estimate_test {

constexpr double kEndTime = 0.5;  // [s]

// The arm with structural damping mu [s].
Model Arm(double damping) {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/";
  ModelSpec spec = LoadModelSpec(dir + "urdf/beam_arm.urdf", dir + "yaml/beam_arm_swing.yaml");
  spec.beams[0].damping = damping;
  spec.solver.t_end = kEndTime;
  return BuildModel(spec);
}

// The model's nodes at time t moved by `motion(node, t, start, &node_state)`, after four steps of h booked as
// accepted steps, ending at `end_time`.
template <typename Motion>
State AfterSteps(const Model& model, double h, double end_time, const Motion& motion) {
  auto at = [&](double t) {
    State state = model.initial_state();
    state.t = t;
    for (int k = 0; k < model.num_nodes(); ++k) motion(k, t, model.initial_state().nodes[k], &state.nodes[k]);
    return state;
  };
  State state = at(end_time - 4 * h);
  for (int step = 0; step < 4; ++step) {
    State end = at(state.t + h);
    RecordStepHistory(state, h, &end);
    state = std::move(end);
  }
  return state;
}

TEST(DampedDeformationEstimate, RigidTurnOfADampedBeamCountsInFull) {
  // The arm turning rigidly at 10 rad/s about a vertical axis away from it: its nodes' x''' is Omega^2 times their
  // speed and no damping removes it, so the damped arm's estimate is the undamped one's (dividing the whole x'''
  // by mu Omega^2 (t_end - t) / 2 = 20 would give 1/20). Left over: the chord of a step against the rigid rate at
  // its midpoint, (Omega h)^2 / 12 = 2e-6 relative.
  const double spin = 10.0, h = 5.0e-4;
  auto turn = [&](int, double t, const NodeState& start, NodeState* node) {
    const Mat3 R = Exp(Vec3(0.0, 0.0, spin * t));
    const Vec3 axis_point(-0.4, 0.3, 0.0);
    node->x = axis_point + R * (start.x - axis_point);
    node->R = R * start.R;
    node->w = Vec3(0.0, 0.0, spin);
    node->v = node->w.cross(node->x - axis_point);
  };
  const double undamped = EstimateLocalError(Arm(0.0), AfterSteps(Arm(0.0), h, 0.1, turn)).error;
  const double damped = EstimateLocalError(Arm(1.0), AfterSteps(Arm(1.0), h, 0.1, turn)).error;
  ASSERT_GT(undamped, 0.0);
  EXPECT_NEAR(damped / undamped, 1.0, 1.0e-5);
}

TEST(DampedDeformationEstimate, OneBendingModeIsDividedByItsDecayOverTheTimeLeft) {
  // The beam nodes move as one mode x_n = a_n sin(omega t) e_z with a zero-mean shape (no rigid part), the tip
  // body at rest: each node's entry is divided by D_n = mu omega^2 (t_end - t) |a_n| / (2 max |a|) where above 1.
  // Near t = 0 (the rates' crest) the divided differences give omega^2 within (omega h)^2: bound 1e-4.
  const double omega = 2.0 * M_PI * 50.0, h = 1.0e-5, mu = 4.0e-3, end_time = 2.0 * h;
  const Model undamped_model = Arm(0.0);
  const std::vector<int>& beam_nodes = undamped_model.beams()[0].nodes;
  std::vector<double> shape(undamped_model.num_nodes(), 0.0);
  double largest = 0;
  for (size_t j = 0; j < beam_nodes.size(); ++j) {
    shape[beam_nodes[j]] = static_cast<double>(j) - 0.5 * static_cast<double>(beam_nodes.size() - 1);
    largest = std::max(largest, std::abs(shape[beam_nodes[j]]));
  }
  auto mode = [&](int k, double t, const NodeState& start, NodeState* node) {
    node->x = start.x + Vec3(0.0, 0.0, shape[k] * std::sin(omega * t));
    node->v = Vec3(0.0, 0.0, shape[k] * omega * std::cos(omega * t));
  };
  const double undamped = EstimateLocalError(undamped_model, AfterSteps(undamped_model, h, end_time, mode)).error;
  const Model damped_model = Arm(mu);
  const double damped = EstimateLocalError(damped_model, AfterSteps(damped_model, h, end_time, mode)).error;
  // Entries are |a_n| omega^3 (common factors cancel in the ratio of the two RMS norms).
  double sum_undamped = 0, sum_damped = 0;
  for (int k : beam_nodes) {
    const double decay = std::max(1.0, 0.5 * mu * omega * omega * (kEndTime - end_time) * std::abs(shape[k]) / largest);
    sum_undamped += shape[k] * shape[k];
    sum_damped += std::pow(shape[k] / decay, 2);
  }
  ASSERT_GT(undamped, 0.0);
  EXPECT_NEAR(damped / undamped, std::sqrt(sum_damped / sum_undamped), 1.0e-4 * std::sqrt(sum_damped / sum_undamped));
}

}  // namespace damped_deformation_estimate_test
}  // namespace flexmbd
