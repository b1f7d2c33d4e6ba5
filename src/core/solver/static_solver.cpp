#include "flexmbd/solver/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/joint_rates.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/touched_stops.hpp"
#include "static_increment.hpp"

namespace flexmbd {
namespace {
// A turn [rad]. An equilibrium with a joint (not driven) turned further from its start passed the configuration it
// started from, and is not the one nearest to the start that a user expects.
constexpr double kTurn = 2.0 * 3.14159265358979323846;

// Multipliers to start from when the state has none: those that hold the joints when the model is released from
// rest there (theory (E2)), scaled to the first load step. With zero multipliers the first tangent has no
// geometric stiffness of the joints, and a mechanism held by gravity alone (a hanging pendulum) is singular in
// it. A model without inertia has no such multipliers and starts from zero.
void StartFromReleaseMultipliers(const Model& model, double load_factor, State* state) {
  if (model.num_multipliers() == 0 || !state->lambda.isZero(0.0)) return;
  try {
    state->lambda = load_factor * WithConsistentMotion(model, *state).lambda;
  } catch (const SolverError&) {
    state->lambda.setZero();
  }
}

// A joint that only an open stop can hold (a slider with no spring pushed along its travel, a hinge at a dead point
// such as a horizontal pendulum) has no stiffness, and its iteration matrix is singular: no increment moves it onto
// the stop. The stop it rests on is the one its loads push it towards: of the open stops not released on a variable
// no drive holds, the nearest that the joint, released from rest at the start, accelerates towards. A rigid one is
// closed as a touched one is (its row g_f = 0 lands the joint on it); an elastic one has no row to close, so the
// model is moved along its motion released from rest until the joint is just past the stop (the increment rule's
// landing), where the stop's static stiffness holds it. One whose force then pulls is opened again
// (ReleasePullingStops). Returns whether any was closed or reached.
// The motion of the model released from rest at `start` into *motion; false if it has none: a model with motions
// that have no inertia (a beam node without rotary inertia) has no accelerations to tell the loads' direction by.
bool ReleaseFromRest(const Model& model, const State& start, State* motion) {
  *motion = start;
  for (NodeState& n : motion->nodes) n.v = n.w = Vec3::Zero();
  try {
    *motion = WithConsistentMotion(model, *motion);
  } catch (const SolverError&) {
    return false;
  }
  return true;
}

// `released_motion` is the model's motion released from rest at *start, null if it has none (ReleaseFromRest).
bool HoldPushedJoints(const Model& model, const StaticIncrement& increment_rule, const std::vector<bool>& released,
                      const State* released_motion, State* start) {
  // Without accelerations the nearest rigid stop is closed whichever way it lies, and if it pulls, opened again and
  // released, and the next nearest closed.
  const bool directed = released_motion != nullptr;
  const Eigen::VectorXd& accelerations =
      directed ? released_motion->qddot_prev : start->qddot_prev;  // read if directed
  std::vector<int> nearest(model.num_variables(), -1);
  const std::vector<const JointStop*>& stops = model.stop_effects();
  for (size_t k = 0; k < stops.size(); ++k) {
    const JointStop& stop = *stops[k];
    const int v = stop.variable();
    const double gap = stop.Gap(start->q[v]);
    const bool pushed = directed ? stop.GapRate(accelerations[v]) < 0.0 : stop.rigid();
    if (released[k] || model.driven(v) || start->effects[stop.slot()].mode != JointStop::kOpen || !pushed ||
        (!stop.rigid() && gap <= 0.0)) {
      continue;
    }
    if (nearest[v] < 0 || gap < stops[nearest[v]]->Gap(start->q[v])) nearest[v] = static_cast<int>(k);
  }
  bool held = false;
  // The release motion's time scale [s^2] that takes the farthest pushed elastic stop's joint twice its gap: the
  // landing ends the move just past the first stop met.
  double move = 0;
  for (int k : nearest) {
    if (k < 0) continue;
    const JointStop& stop = *stops[k];
    held = true;
    if (stop.rigid()) {
      start->effects[stop.slot()].mode = JointStop::kContact;
      continue;
    }
    const int v = stop.variable();
    move = std::max(move, -2.0 * stop.Gap(start->q[v]) / stop.GapRate(accelerations[v]));
  }
  if (move > 0) {
    Eigen::VectorXd increment = Eigen::VectorXd::Zero(model.num_unknowns());
    for (int k = 0; k < model.num_nodes(); ++k) {
      increment.segment<3>(model.node_unknown(k)) = move * released_motion->nodes[k].a_prev;
      increment.segment<3>(model.node_unknown(k) + 3) = move * released_motion->nodes[k].alpha_prev;
    }
    for (int v = 0; v < model.num_variables(); ++v) increment[model.variable_unknown(v)] = move * accelerations[v];
    // No residual: a move along the loads' own motion is downhill, and is only bounded in its turns.
    increment_rule.Apply(Eigen::VectorXd::Zero(model.num_unknowns()), increment, released, start);
  }
  return held;
}

// Opens the rigid stops that hold the equilibrium with a contact force that pulls (the load takes the joint off the
// stop) in the start, and releases them: a landing does not close them again. Returns whether any was opened.
bool ReleasePullingStops(const Model& model, const State& equilibrium, State* start, std::vector<bool>* released) {
  bool opened = false;
  StepContextBuilder builder(model);
  const StepContext& at_equilibrium = builder.AtState(equilibrium);
  for (size_t k = 0; k < model.stop_effects().size(); ++k) {
    const JointStop& stop = *model.stop_effects()[k];
    if (equilibrium.effects[stop.slot()].mode != JointStop::kContact || !stop.rigid() ||
        stop.Sample(equilibrium, at_equilibrium).force >= 0.0) {
      continue;
    }
    start->effects[stop.slot()].mode = JointStop::kOpen;
    (*released)[k] = true;
    opened = true;
  }
  return opened;
}

// An equilibrium the user cannot have meant is no solution: one with a joint turned by more than a turn from its
// start (Newton went past the nearest one), or beyond a rigid stop that is open there (it passed the stop).
void RefuseOutOfReach(const Model& model, const State& start, const State& equilibrium, StaticResult* result) {
  for (int v : AngularVariables(model)) {
    if (model.driven(v) || std::abs(equilibrium.q[v] - start.q[v]) <= kTurn) continue;
    result->converged = false;
    result->turned_variable = v;
    result->turn = equilibrium.q[v] - start.q[v];
    return;
  }
  for (size_t k = 0; k < model.stop_effects().size(); ++k) {
    const JointStop& stop = *model.stop_effects()[k];
    const bool open = equilibrium.effects[stop.slot()].mode == JointStop::kOpen;
    if (!stop.rigid() || !open || stop.Gap(equilibrium.q[stop.variable()]) >= -kConstraintTolerance) continue;
    result->converged = false;
    result->passed_stop = static_cast<int>(k);
    return;
  }
}

// Elastic stops that the equilibrium presses (a negative gap) are in contact, the mode a step ending there would commit
// (ElasticStop::Commit), as the rigid stops that hold are closed: a run started from the equilibrium has each contact
// from its start (Simulation::Begin).
void MarkPressedElasticStops(const Model& model, State* state) {
  for (const JointStop* stop : model.stop_effects()) {
    EffectState& effect = state->effects[stop->slot()];
    if (stop->rigid() || effect.mode == JointStop::kRetracted) continue;
    effect.mode = stop->Gap(state->q[stop->variable()]) < 0.0 ? JointStop::kContact : JointStop::kOpen;
  }
}

// The joint variable a singular iteration matrix left undetermined (its zero pivot) when only an open elastic stop
// could hold it and the model released from rest at `start` has no accelerations to tell which one it rests on
// (`directed` false, ReleaseFromRest); else -1.
int UndirectedVariable(const Model& model, const State& start, const NewtonReport& last, bool directed) {
  const int v = last.singular_unknown - model.variable_unknown(0);
  if (last.singular_unknown < 0 || v < 0 || v >= model.num_variables() || model.driven(v)) return -1;
  const std::vector<const JointStop*>& stops = model.stop_effects();
  const bool elastic = std::any_of(stops.begin(), stops.end(), [&](const JointStop* stop) {
    return stop->variable() == v && !stop->rigid() && start.effects[stop->slot()].mode == JointStop::kOpen;
  });
  return elastic && !directed ? v : -1;
}

StaticResult SolveLoadSteps(const Model& model, SparseSystem* system, const std::vector<bool>& released,
                            State* state) {
  StepContextBuilder builder(model);
  builder.set_geometric_stiffness(true);
  StaticResult result;
  for (NodeState& n : state->nodes) n.v = n.w = n.a_prev = n.alpha_prev = n.a_prev2 = n.alpha_prev2 = Vec3::Zero();
  const int n_steps = model.solver().load_steps;
  StartFromReleaseMultipliers(model, 1.0 / n_steps, state);
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model.num_unknowns());
  // Full Newton: a load step moves the structure far from where the last tangent was assembled, and the simplified
  // iteration's contraction test, one max norm over unknowns of different units, let the inflow states (m/s) hide
  // a stale tangent's divergence in the motion (docs/theory.md, "Newton iteration").
  NewtonOptions options;
  options.fresh_tangent_every_iteration = true;
  const StaticIncrement increment_rule(model);
  const double round_off = RoundOffFloor(model.length_scale());
  for (int step = 1; step <= n_steps; ++step) {
    const double load_factor = static_cast<double>(step) / n_steps;
    result.load_steps = step;
    // The joints' reactions grow with the load: the last step's, raised to this one, start it (exact for loads
    // carried without deformation, such as a pendulum's weight, which then converges on its first iteration).
    if (step > 1) state->lambda *= static_cast<double>(step) / (step - 1);
    double travelled = 0;  // size of the motion within this load step, for the increment test
    result.last = SolveNewton(
        model, system, model.solver().tol, model.solver().max_iterations, round_off,
        [&](int, bool) -> const StepContext& {
          unknowns.setZero();
          unknowns.tail(model.num_multipliers()) = state->lambda;
          return builder.Static(*state, unknowns, state->t, load_factor);
        },
        [&](const Eigen::VectorXd& increment) {
          travelled = std::max(travelled, increment_rule.Apply(system->residual(), increment, released, state));
          return travelled + kMotionFloor;
        },
        options);
    system->set_factorisation_key(std::numeric_limits<double>::quiet_NaN());  // a static tangent: not reusable
    result.iterations += result.last.iterations;
    if (!result.last.converged) return result;
  }
  state->qdot = JointRates(model, *state);
  state->element_state_rates.setZero();
  MarkPressedElasticStops(model, state);
  result.converged = true;
  return result;
}

// Friction holds nothing in a static analysis (docs/theory.md, "Friction"): a joint it would hold in a dynamic run
// is free here, which a user who gave the friction does not expect.
std::string FrictionLeftOut(const Model& model) {
  if (model.frictions().empty()) return "";
  std::string names;
  for (const FrictionInfo& friction : model.frictions()) {
    names += (names.empty() ? "" : ", ") + model.variable_names()[friction.variable];
  }
  return "; friction (on " + names + ") is left out of a static analysis: to hold a joint where friction would, give "
         "it initial.static_hold";
}

}  // namespace

StaticResult SolveStatic(const Model& model, SparseSystem* system, State* state) {
  const State initial = *state;
  State start = initial;
  // A static analysis has no time steps whose events would close the stops a joint touches, and a joint resting on its
  // stop with nothing else to hold it (a block on a frictionless incline, a hinged blade on its droop stop) had a
  // singular iteration matrix: they are closed, their row g_f = 0 (C2a).
  CloseTouchedRigidStops(model, RoundOffFloor(model.length_scale()), &start);
  // Each closed stop either holds (a contact force >= 0) or is opened and the equilibrium solved again without it.
  std::vector<bool> released(model.stop_effects().size(), false);
  const StaticIncrement increment_rule(model);
  StaticResult result;
  // Whether the model released from rest at the last start has accelerations: HoldPushedJoints leaves a start it
  // holds nothing in as it was, so the last release motion is the final start's.
  bool directed = true;
  while (true) {
    *state = start;
    result = SolveLoadSteps(model, system, released, state);
    bool again = false;
    if (result.converged) {
      again = ReleasePullingStops(model, *state, &start, &released);
    } else if (result.last.singular) {
      State released_motion;
      directed = ReleaseFromRest(model, start, &released_motion);
      again = HoldPushedJoints(model, increment_rule, released, directed ? &released_motion : nullptr, &start);
    }
    if (!again) break;
  }
  if (result.converged) RefuseOutOfReach(model, initial, *state, &result);
  if (result.last.singular) result.undirected_variable = UndirectedVariable(model, start, result.last, directed);
  return result;
}

std::string DescribeStaticFailure(const Model& model, const StaticResult& result) {
  const SolverSpec& solver = model.solver();
  std::ostringstream text;
  if (result.turned_variable >= 0) {
    text << "static analysis failed: the equilibrium Newton found turns joint "
         << model.variable_names()[result.turned_variable] << " by " << result.turn << " rad ("
         << result.turn / kTurn << " turns) from its start, more than a turn: not the equilibrium nearest to the "
         << "start; start the joint within a turn of the equilibrium you expect";
    return text.str();
  }
  if (result.passed_stop >= 0) {
    const StopInfo& stop = model.stops()[result.passed_stop];
    text << "static analysis failed: the equilibrium Newton found lies beyond stop " << stop.joint << ' ' << stop.stop
         << ", which it passed; start the joint closer to the equilibrium you expect";
    return text.str();
  }
  text << "static analysis failed in load increment " << result.load_steps << " of " << solver.load_steps
       << " (load factor " << static_cast<double>(result.load_steps) / solver.load_steps << "): ";
  if (result.last.singular) {
    text << "singular iteration matrix after " << result.last.iterations << " Newton iteration(s)";
    if (result.undirected_variable >= 0) {
      text << ": joint " << model.variable_names()[result.undirected_variable]
           << " has no stiffness, nothing holds it; only its elastic stops could, and the load cannot tell which one "
              "it rests on, as the model has no inertia to release it with (a beam node without rotary inertia); "
              "give the beam rotary inertia (section m_ii), use rigid stops, start the joint on the stop, or run a "
              "dynamic analysis";
      return text.str();
    }
  } else {
    text << "Newton did not converge in " << result.last.iterations << " iterations (solver.max_iterations "
         << solver.max_iterations << ")";
  }
  if (result.last.worst_unknown >= 0) {
    text << "; worst residual at " << model.DescribeUnknown(result.last.worst_unknown) << " (force "
         << result.last.force_residual << " relative, constraint " << result.last.constraint_residual << ")";
  }
  if (result.last.singular) {
    text << "; check that every part is held in the equilibrium (a joint free to move with nothing to stop it, "
            "no spring, stop or drive, has none) and for constraints that repeat each other";
    text << FrictionLeftOut(model);
  } else {
    text << "; try more load increments (solver.load_steps), a larger solver.max_iterations or solver.tol, or "
            "check that an equilibrium exists (a load that nothing holds has none)";
  }
  return text.str();
}

}  // namespace flexmbd
