// The local error estimate on a damped beam (docs/theory.md (T12b), (T12c)): the third derivative of the beam's rigid
// motion (the rigid velocity field that fits its nodes' rates) counts in full, and that of its deformation relative to
// the rigid motion is divided by the deformation's decay over a horizon H, mu omega^2 H / 2, with omega^2 = |x'''| /
// |x'| of one mode and H the time the motion takes to move by the model's size at its peak speed (by a radian at its
// peak spin while no node has moved), or the time run if longer; the deformation's velocity error, omega |x''|, counts
// beside it. Checked on the flexible arm of test/data with prescribed node motions booked as accepted steps.

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

// The arm with structural damping mu [s].
Model Arm(double damping) {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/";
  ModelSpec spec = LoadModelSpec(dir + "urdf/beam_arm.urdf", dir + "yaml/beam_arm_swing.yaml");
  spec.beams[0].damping = damping;
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
  // by mu Omega^2 H / 2, H at least the 0.1 s run, would give 1/5 at most). Left over: the chord of a step against
  // the rigid rate at its midpoint, (Omega h)^2 / 12 = 2e-6 relative.
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

// A bending shape of the arm's beam nodes, a_j = (j - c)^2 - mean over the node index j (the nodes are equally
// spaced): symmetric and of zero mean, so no rigid velocity field fits any part of it; the tip body has none.
std::vector<double> BendingShape(const Model& model) {
  const std::vector<int>& nodes = model.beams()[0].nodes;
  const double centre = 0.5 * static_cast<double>(nodes.size() - 1);
  std::vector<double> shape(model.num_nodes(), 0.0);
  double mean = 0;
  for (size_t j = 0; j < nodes.size(); ++j) mean += std::pow(static_cast<double>(j) - centre, 2) / nodes.size();
  for (size_t j = 0; j < nodes.size(); ++j) shape[nodes[j]] = std::pow(static_cast<double>(j) - centre, 2) - mean;
  return shape;
}

TEST(DampedDeformationEstimate, OneBendingModeIsDividedByItsDecayOverTheHorizon) {
  // The beam nodes move as one mode x_n = a_n sin(omega t) e_z, the tip body at rest: each node's entry is divided by
  // D_n = mu omega^2 H |a_n| / (2 max |a|) where above 1, H = L / (omega max |a|) the time the mode's peak speed takes
  // to cover the model's size L (9e-4 s here, longer than the 2e-5 s run: D = 44 at the largest amplitude), and gains
  // the velocity part omega_n |x''| with omega_n^2 = omega^2 |a_n| / max |a|: near t = 0 (the rates' crest; x'' taken
  // at t = h from the newest two steps) |x''| = omega^2 |a_n| sin(omega h), a share (|a_n| / max |a|) sin^2(omega h) of
  // the square. The divided differences give omega^2 and x''' within (omega h)^2 = 1e-3 relative, on terms that the
  // ratio of two runs of the same motion cancels to 1e-5: bound 1e-4.
  const double omega = 2.0 * M_PI * 50.0, h = 1.0e-5, mu = 1.0, end_time = 2.0 * h;
  const Model undamped_model = Arm(0.0);
  const std::vector<double> shape = BendingShape(undamped_model);
  double largest = 0;
  for (double a : shape) largest = std::max(largest, std::abs(a));
  auto mode = [&](int k, double t, const NodeState& start, NodeState* node) {
    node->x = start.x + Vec3(0.0, 0.0, shape[k] * std::sin(omega * t));
    node->v = Vec3(0.0, 0.0, shape[k] * omega * std::cos(omega * t));
  };
  const double undamped = EstimateLocalError(undamped_model, AfterSteps(undamped_model, h, end_time, mode)).error;
  const Model damped_model = Arm(mu);
  const double damped = EstimateLocalError(damped_model, AfterSteps(damped_model, h, end_time, mode)).error;
  // Entries are |a_n| omega^3 (common factors cancel in the ratio of the two RMS norms).
  double sum_undamped = 0, sum_damped = 0;
  const double velocity_share = std::pow(std::sin(omega * h), 2);
  for (int k : undamped_model.beams()[0].nodes) {
    const double share = std::abs(shape[k]) / largest;
    const double horizon = std::max(end_time, undamped_model.length_scale() / (largest * omega));
    const double decay = std::max(1.0, 0.5 * mu * omega * omega * horizon * share);
    sum_undamped += shape[k] * shape[k];
    sum_damped += shape[k] * shape[k] * (1.0 + share * velocity_share) / (decay * decay);
  }
  const double expected = std::sqrt(sum_damped / sum_undamped);
  ASSERT_GT(undamped, 0.0);
  EXPECT_NEAR(damped / undamped, expected, 1.0e-4 * expected);
}

TEST(DampedDeformationEstimate, OneBendingModeWeighsAlikeAtItsCrestAndItsTurn) {
  // A mode's local error is a phase error: the position part h^3 |x'''| / 12 vanishes where the mode turns (x' = 0)
  // and its velocity part, counted as omega_n |x''|, where it crosses (x'' = 0). With both, a node weighs
  // |a_n| omega^3 at the crest and |a_n| omega_n omega^2 at the turn, omega_n^2 = omega^2 |a_n| / max |a| (T12c):
  // the node of largest amplitude alike, the RMS over nodes by sqrt(sum a_n^2 (|a_n| / max |a|) / sum a_n^2). Left
  // over: the crest's velocity share sin^2(omega h) = 1e-3 of the square, the turn's position share
  // sin^2(omega h / 2) = 2.5e-4 and the divided differences' (omega h)^2 = 1e-3: bound 3e-3. The position part
  // alone weighs 0.16% at the turn (measured). Damping too small to discount (D = 1).
  const double omega = 2.0 * M_PI * 50.0, h = 1.0e-5, mu = 1.0e-9;
  const Model model = Arm(mu);
  const std::vector<double> shape = BendingShape(model);
  auto mode = [&](int k, double t, const NodeState& start, NodeState* node) {
    node->x = start.x + Vec3(0.0, 0.0, shape[k] * std::sin(omega * t));
    node->v = Vec3(0.0, 0.0, shape[k] * omega * std::cos(omega * t));
  };
  // Crest: x''' taken at t = h / 2 (cos 1 - 1e-3), x'' at t = h. Turn: x'' at t = pi / (2 omega). Both judged
  // against the mode's peak speed (four steps at the turn would not have seen it).
  double largest = 0;
  for (double a : shape) largest = std::max(largest, std::abs(a));
  auto estimate = [&](double end_time) {
    State state = AfterSteps(model, h, end_time, mode);
    state.peak_speed = largest * omega;
    return EstimateLocalError(model, state).error;
  };
  const double crest = estimate(2.0 * h);
  const double turn = estimate(0.5 * M_PI / omega + h);
  double sum = 0, sum_turn = 0;
  for (double a : shape) {
    sum += a * a;
    sum_turn += a * a * std::abs(a) / largest;
  }
  const double expected = std::sqrt(sum_turn / sum);
  ASSERT_GT(crest, 0.0);
  EXPECT_NEAR(turn / crest, expected, 3.0e-3 * expected);
}

TEST(DampedDeformationEstimate, ANodeSpinningOnItsOwnIsNoTurnOfTheBeam) {
  // The root node alone turns about y, angle c t^3 (a released root, whose small rotary inertia lets it spin ahead of
  // the beam): the other nodes do not move, so no rigid motion fits the beam's rates and the root's spin is
  // deformation, divided by D = mu omega^2 H / 2 with omega^2 = |w'''| / |w| = 2 / t^2 and H = 1 / (3 c t^2), the time
  // its peak spin takes to turn a radian (no node has moved; longer than the 0.1 s run): D = 33 here, and the velocity
  // part omega |w''| = 1.4 |w'''| adds a factor sqrt(1 + 1.4^2) = 1.7, so the damped estimate is 1.7 / 33 = 0.052 of
  // the undamped one (bound 0.1). A rigid turn taken as the nodes' mean spin would count w'''/7 in full at every node's
  // translation, above its floor alone here (no node moves: peak speed 0).
  const double c = 100.0, h = 1.0e-4, end_time = 0.1, mu = 1.0;
  auto root_spins = [&](const Model& model) {
    const int root = model.beams()[0].nodes.front();
    return [&, root](int k, double t, const NodeState& start, NodeState* node) {
      if (k != root) return;
      node->R = Exp(Vec3(0.0, c * t * t * t, 0.0)) * start.R;
      node->w = Vec3(0.0, 3.0 * c * t * t, 0.0);
    };
  };
  const Model undamped_model = Arm(0.0), damped_model = Arm(mu);
  const double undamped =
      EstimateLocalError(undamped_model, AfterSteps(undamped_model, h, end_time, root_spins(undamped_model))).error;
  const ErrorEstimate damped =
      EstimateLocalError(damped_model, AfterSteps(damped_model, h, end_time, root_spins(damped_model)));
  ASSERT_GT(undamped, 0.0);
  EXPECT_LT(damped.error / undamped, 0.1);
  EXPECT_EQ(damped.worst_unknown, damped_model.node_unknown(damped_model.beams()[0].nodes.front()) + 3);
}

}  // namespace damped_deformation_estimate_test
}  // namespace flexmbd
