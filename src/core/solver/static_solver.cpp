#include "flexmbd/solver/static_solver.hpp"

#include <limits>

#include "flexmbd/common/error.hpp"
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

}  // namespace

StaticResult SolveStatic(const Model& model, SparseSystem* system, State* state) {
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
  for (int step = 1; step <= n_steps; ++step) {
    const double load_factor = static_cast<double>(step) / n_steps;
    result.load_steps = step;
    // The joints' reactions grow with the load: the last step's, raised to this one, start it (exact for loads
    // carried without deformation, such as a pendulum's weight, which then converges on its first iteration).
    if (step > 1) state->lambda *= static_cast<double>(step) / (step - 1);
    double travelled = 0;  // size of the motion within this load step, for the increment test
    result.last = SolveNewton(
        model, system, model.solver().tol, model.solver().max_iterations, RoundOffFloor(model.length_scale()),
        [&](int, bool) -> const StepContext& {
          unknowns.setZero();
          unknowns.tail(model.num_multipliers()) = state->lambda;
          return builder.Static(*state, unknowns, state->t, load_factor);
        },
        [&](const Eigen::VectorXd& increment) {
          for (int k = 0; k < model.num_nodes(); ++k) {
            NodeState& n = state->nodes[k];
            n.x += increment.segment<3>(model.node_unknown(k));
            n.R = n.R * Exp(increment.segment<3>(model.node_unknown(k) + 3));
          }
          for (int k = 0; k < model.num_variables(); ++k) state->q[k] += increment[model.variable_unknown(k)];
          state->element_states += increment.segment(model.element_state_unknown(0), model.num_element_states());
          state->lambda += increment.tail(model.num_multipliers());
          travelled = std::max(travelled, increment.head(model.num_unknowns() - model.num_multipliers()).cwiseAbs().maxCoeff());
          return travelled + kMotionFloor;
        },
        options);
    system->set_factorisation_key(std::numeric_limits<double>::quiet_NaN());  // a static tangent: not reusable
    result.iterations += result.last.iterations;
    if (!result.last.converged) return result;
  }
  state->qdot = JointRates(model, *state);
  state->element_state_rates.setZero();
  result.converged = true;
  return result;
}

}  // namespace flexmbd
