#include "static_increment.hpp"

#include <algorithm>
#include <cmath>

#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/joints/joint.hpp"
#include "flexmbd/math/so3.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/newton.hpp"

namespace flexmbd {
namespace {
// The largest turn of a joint in one static iteration [rad]: within it the sines and cosines that carry the joint's
// loads depart from their linearisation by at most 12%. A joint near a dead point (a pendulum near the horizontal)
// has almost no stiffness, and its Newton increment, the load over that stiffness, turned it by up to a hundred
// radians: a pendulum 0.01 rad above its stop landed 15.75 turns away.
constexpr double kLargestTurn = 0.5;

// An increment that would close an open elastic stop is cut to end just past it: an open stop has no stiffness in
// the tangent the increment came from, and the whole increment can end deep inside the stop (a flap floating to 3
// deg through its 0.5 deg stop), from where Newton diverges. Just past it, the next tangent holds the stop. As a
// dynamic step lands on a contact ((C5), kEventLanding), but on the contact's side.
constexpr double kStopLanding = 1.02;

}  // namespace

std::vector<int> AngularVariables(const Model& model) {
  std::vector<int> angular;
  for (const Joint* joint : model.joints()) {
    for (const RotationFactor& factor : joint->kinematics().rotations) {
      angular.push_back(joint->first_variable() + factor.variable);
    }
  }
  return angular;
}

StaticIncrement::StaticIncrement(const Model& model)
    : model_(model), angular_(AngularVariables(model)), round_off_(RoundOffFloor(model.length_scale())) {}

void StaticIncrement::BoundTurns(const Eigen::VectorXd& residual, Eigen::VectorXd* increment) const {
  double turn = 0;
  for (int v : angular_) turn = std::max(turn, std::abs((*increment)[model_.variable_unknown(v)]));
  if (turn <= kLargestTurn) return;
  // An increment that long came from a tangent that says little of where the equilibrium is, and one along which
  // the loads do negative work (the residual is the gradient of the potential where the constraints hold) heads for
  // an unstable equilibrium: a pendulum above the horizontal, its stiffness negative, for standing upright. It is
  // turned round, downhill, and its multipliers left to the next iteration.
  const int n_motion = 6 * model_.num_nodes() + model_.num_variables();
  const bool uphill = residual.head(n_motion).dot(increment->head(n_motion)) > 0;
  const double scale = kLargestTurn / turn;
  increment->head(model_.num_kinematic()) *= uphill ? -scale : scale;
  increment->tail(model_.num_multipliers()) *= uphill ? 0.0 : scale;
}

double StaticIncrement::Apply(const Eigen::VectorXd& residual, Eigen::VectorXd increment,
                              const std::vector<bool>& released, State* state) const {
  BoundTurns(residual, &increment);
  // The fraction of the increment to take: 1, or less where it would pass an open stop.
  const std::vector<const JointStop*>& stops = model_.stop_effects();
  double fraction = 1.0;
  int landing_on = -1;  // the rigid stop it lands on
  for (size_t k = 0; k < stops.size(); ++k) {
    const JointStop& stop = *stops[k];
    const bool rigid_closed = stop.rigid() && (state->effects[stop.slot()].mode != JointStop::kOpen || released[k]);
    const double q = state->q[stop.variable()];
    const double g_i = stop.Gap(q), g_f = stop.Gap(q + increment[model_.variable_unknown(stop.variable())]);
    if (rigid_closed || g_i <= round_off_ || g_f >= 0) continue;
    const double reach = g_i / (g_i - g_f);
    const double landing = stop.rigid() ? reach : kStopLanding * reach;
    if (landing >= fraction) continue;
    fraction = landing;
    landing_on = stop.rigid() ? static_cast<int>(k) : -1;
  }
  increment *= fraction;
  const Eigen::VectorXd q_start = state->q;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    NodeState& n = state->nodes[k];
    n.x += increment.segment<3>(model_.node_unknown(k));
    n.R = n.R * Exp(increment.segment<3>(model_.node_unknown(k) + 3));
  }
  for (int k = 0; k < model_.num_variables(); ++k) state->q[k] += increment[model_.variable_unknown(k)];
  state->element_states += increment.segment(model_.element_state_unknown(0), model_.num_element_states());
  state->lambda += increment.tail(model_.num_multipliers());
  // A rigid stop landed on holds from here (its row g_f = 0, (C2a)).
  if (landing_on >= 0) state->effects[stops[landing_on]->slot()].mode = JointStop::kContact;
  double travelled = increment.head(model_.num_kinematic()).cwiseAbs().maxCoeff();
  for (const JointStop* stop : stops) {
    const int v = stop->variable();
    const bool acts = !stop->rigid() && state->effects[stop->slot()].mode != JointStop::kRetracted;
    if (!acts || stop->Gap(q_start[v]) > 0) continue;
    state->q[v] = static_cast<const ElasticStop*>(stop)->StaticPosition(q_start[v], state->q[v] - q_start[v]);
    travelled = std::max(travelled, std::abs(state->q[v] - q_start[v]));
  }
  return travelled;
}

}  // namespace flexmbd
