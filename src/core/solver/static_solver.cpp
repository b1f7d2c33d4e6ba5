#include "flexmbd/solver/static_solver.hpp"

#include <algorithm>
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

namespace flexmbd {
namespace {

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

// An increment that would close an open elastic stop is cut to end just past it: an open stop has no stiffness in
// the tangent the increment came from, and the whole increment can end deep inside the stop (a flap floating to 3
// deg through its 0.5 deg stop), from where Newton diverges. Just past it, the next tangent holds the stop. As a
// dynamic step lands on a contact ((C5), kEventLanding), but on the contact's side.
constexpr double kStopLanding = 1.02;

// The fraction of `increment` to take: 1, or less where it would close one of `stops` from `state`.
double StopLandingFraction(const std::vector<const JointStop*>& stops, const Model& model, const State& state,
                           const Eigen::VectorXd& increment, double round_off) {
  double fraction = 1.0;
  for (const JointStop* stop : stops) {
    const double q = state.q[stop->variable()];
    const double g_i = stop->Gap(q), g_f = stop->Gap(q + increment[model.variable_unknown(stop->variable())]);
    if (g_i > round_off && g_f < 0) fraction = std::min(fraction, kStopLanding * g_i / (g_i - g_f));
  }
  return std::min(fraction, 1.0);
}

std::vector<const JointStop*> ElasticStops(const Model& model) {
  std::vector<const JointStop*> stops;
  for (const JointStop* stop : model.stop_effects()) {
    if (!stop->rigid()) stops.push_back(stop);
  }
  return stops;
}

// Rigid stops that the joint touches (gap within round-off) are closed: a static analysis has no time steps whose
// events would close them, and a joint resting on its stop with nothing else to hold it (a block on a frictionless
// incline, a hinged blade on its droop stop) had a singular iteration matrix. In contact the stop's row is g_f = 0
// (C2a). Returns whether any was closed.
bool CloseTouchedRigidStops(const Model& model, double round_off, State* state) {
  bool closed = false;
  for (const JointStop* stop : model.stop_effects()) {
    EffectState& effect = state->effects[stop->slot()];
    if (!stop->rigid() || effect.mode != JointStop::kOpen) continue;
    if (stop->Gap(state->q[stop->variable()]) > round_off) continue;
    effect.mode = JointStop::kContact;
    closed = true;
  }
  return closed;
}

// Opens the closed rigid stops of an equilibrium whose contact force pulls (the load takes the joint off the stop).
// Returns whether any was opened.
bool OpenPullingStops(const Model& model, const State& equilibrium, State* start) {
  bool opened = false;
  StepContextBuilder builder(model);
  const StepContext& at_equilibrium = builder.AtState(equilibrium);
  for (const JointStop* stop : model.stop_effects()) {
    EffectState& effect = start->effects[stop->slot()];
    if (effect.mode != JointStop::kContact || stop->Sample(equilibrium, at_equilibrium).force >= 0.0) continue;
    effect.mode = JointStop::kOpen;
    opened = true;
  }
  return opened;
}

// Elastic stops that the equilibrium presses (a negative gap) are in contact, the mode a step ending there would commit
// (ElasticStop::Commit), as the rigid stops that hold are closed: a run started from the equilibrium has each contact
// from its start (Simulation::Begin).
void MarkPressedElasticStops(const Model& model, State* state) {
  for (const JointStop* stop : ElasticStops(model)) {
    EffectState& effect = state->effects[stop->slot()];
    if (effect.mode == JointStop::kRetracted) continue;
    effect.mode = stop->Gap(state->q[stop->variable()]) < 0.0 ? JointStop::kContact : JointStop::kOpen;
  }
}

StaticResult SolveLoadSteps(const Model& model, SparseSystem* system, State* state) {
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
  const std::vector<const JointStop*> stops = ElasticStops(model);
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
          const double f = StopLandingFraction(stops, model, *state, increment, round_off);
          for (int k = 0; k < model.num_nodes(); ++k) {
            NodeState& n = state->nodes[k];
            n.x += f * increment.segment<3>(model.node_unknown(k));
            n.R = n.R * Exp(f * increment.segment<3>(model.node_unknown(k) + 3));
          }
          for (int k = 0; k < model.num_variables(); ++k) state->q[k] += f * increment[model.variable_unknown(k)];
          state->element_states += f * increment.segment(model.element_state_unknown(0), model.num_element_states());
          state->lambda += f * increment.tail(model.num_multipliers());
          const int n_kinematic = model.num_unknowns() - model.num_multipliers();
          travelled = std::max(travelled, f * increment.head(n_kinematic).cwiseAbs().maxCoeff());
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

}  // namespace

StaticResult SolveStatic(const Model& model, SparseSystem* system, State* state) {
  State start = *state;
  if (!CloseTouchedRigidStops(model, RoundOffFloor(model.length_scale()), &start)) {
    return SolveLoadSteps(model, system, state);
  }
  // Each closed stop either holds (a contact force >= 0) or is opened and the equilibrium solved again without it.
  StaticResult result;
  do {
    *state = start;
    result = SolveLoadSteps(model, system, state);
  } while (result.converged && OpenPullingStops(model, *state, &start));
  return result;
}

std::string DescribeStaticFailure(const Model& model, const StaticResult& result) {
  const SolverSpec& solver = model.solver();
  std::ostringstream text;
  text << "static analysis failed in load increment " << result.load_steps << " of " << solver.load_steps
       << " (load factor " << static_cast<double>(result.load_steps) / solver.load_steps << "): ";
  if (result.last.singular) {
    text << "singular iteration matrix after " << result.last.iterations << " Newton iteration(s)";
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
  } else {
    text << "; try more load increments (solver.load_steps), a larger solver.max_iterations or solver.tol, or "
            "check that an equilibrium exists (a load that nothing holds has none)";
  }
  return text.str();
}

}  // namespace flexmbd
