#include "flexmbd/solver/energy_decaying_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/joint_rates.hpp"
#include "flexmbd/solver/sparse_system.hpp"

namespace flexmbd {
namespace {
// The dissipation of one node's translation or rotation over a step is alpha (dv - h a_prev) . M dv (M the
// node's mass, or its inertia tensor for rotations): it is used only where that product is >= 0, judged with
// the previous step's values beforehand and checked after convergence.
bool Dissipates(const Vec3& dv, const Vec3& dv_lagged, const Mat3& M) { return (dv - dv_lagged).dot(M * dv) >= 0.0; }
}  // namespace

double DissipationFromRhoInf(double rho_inf) {
  // Unresolved-mode limit of (T3)-(T4): rho (1 - rho) = 2 alpha (1 + rho)^2 (docs/theory.md).
  return rho_inf * (1.0 - rho_inf) / (2.0 * (1.0 + rho_inf) * (1.0 + rho_inf));
}

EnergyDecayingIntegrator::EnergyDecayingIntegrator(const Model& model, SparseSystem* system)
    : model_(model),
      system_(system),
      builder_(model),
      alpha_inf_(model.solver().integrator == SolverSpec::Integrator::kEnergyDecaying
                     ? DissipationFromRhoInf(model.solver().rho_inf)
                     : 0.0),
      node_inertia_(model.num_nodes(), Mat3::Identity()) {
  for (const RigidBody* body : model.rigid_bodies()) node_inertia_[body->node()] = body->inertia();
}

std::vector<NodeSchemeCoefficients> EnergyDecayingIntegrator::Coefficients(const State& start) const {
  std::vector<NodeSchemeCoefficients> c(model_.num_nodes());
  if (alpha_inf_ == 0.0 || start.history_steps < 1) return c;
  const double ratio = start.history_steps >= 2 ? 1.0 : 0.0;  // no a_prev2 before the second step
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeState& n = start.nodes[k];
    c[k].alpha_translation = Dissipates(n.a_prev, ratio * n.a_prev2, Mat3::Identity()) ? alpha_inf_ : 0.0;
    c[k].alpha_rotation = Dissipates(n.alpha_prev, ratio * n.alpha_prev2, node_inertia_[k]) ? alpha_inf_ : 0.0;
  }
  return c;
}

bool EnergyDecayingIntegrator::DropEnergyGainingDissipation(const State& start, double h,
                                              std::vector<NodeSchemeCoefficients>* c) const {
  const StepContext& ctx = builder_.context();
  bool dropped = false;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeStep& s = (*ctx.nodes)[k];
    const NodeState& n = start.nodes[k];
    NodeSchemeCoefficients& ck = (*c)[k];
    if (ck.alpha_translation > 0 && !Dissipates(s.v_f - s.v_i, h * n.a_prev, Mat3::Identity())) {
      ck.alpha_translation = 0;
      dropped = true;
    }
    if (ck.alpha_rotation > 0 && !Dissipates(s.w_f - s.w_i, h * n.alpha_prev, node_inertia_[k])) {
      ck.alpha_rotation = 0;
      dropped = true;
    }
  }
  return dropped;
}

Eigen::VectorXd EnergyDecayingIntegrator::Predict(const State& start, double h) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(model_.num_unknowns());
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeState& n = start.nodes[k];
    x.segment<3>(model_.node_unknown(k)) = h * n.v + 0.5 * h * h * n.a_prev;
    x.segment<3>(model_.node_unknown(k) + 3) = h * n.w + 0.5 * h * h * n.alpha_prev;
  }
  const bool has_rates = start.qddot_prev.size() == model_.num_variables();
  for (int k = 0; k < model_.num_variables(); ++k) {
    x[model_.variable_unknown(k)] = h * start.qdot[k] + (has_rates ? 0.5 * h * h * start.qddot_prev[k] : 0.0);
  }
  x.tail(model_.num_multipliers()) = start.lambda;
  return x;
}

StepResult EnergyDecayingIntegrator::Step(const State& start, double h, State* end) {
  std::vector<NodeSchemeCoefficients> coefficients = Coefficients(start);
  const int n_kinematic = model_.num_unknowns() - model_.num_multipliers();
  StepResult result;
  Eigen::VectorXd unknowns;
  do {
    unknowns = Predict(start, h);
    result.newton = SolveNewton(
        model_, system_, model_.solver().tol, model_.solver().max_iterations, NoiseFloor(model_, start),
        [&](int iteration, bool with_tangent) -> const StepContext& {
          // The first tangent leaves out the geometric stiffness of constraint forces and loads (O(h^2)
          // against inertia); a tangent refreshed because convergence was slow includes it.
          builder_.set_geometric_stiffness(with_tangent && iteration > 1);
          return builder_.Dynamic(start, unknowns, h, coefficients);
        },
        [&](const Eigen::VectorXd& increment) {
          unknowns += increment;
          return unknowns.head(n_kinematic).cwiseAbs().maxCoeff();
        });
    if (result.newton.singular) {
      result.status = StepStatus::kSingularMatrix;
      return result;
    }
    if (!result.newton.converged) {
      result.status = StepStatus::kNewtonDiverged;
      return result;
    }
    builder_.Dynamic(start, unknowns, h, coefficients);
  } while (DropEnergyGainingDissipation(start, h, &coefficients));
  Commit(start, unknowns, h, coefficients, end);
  result.error = LocalErrorEstimate(*end, start.h_prev, model_.solver().error_tol);
  const bool too_large = model_.solver().adaptive && result.error > 1.0;
  result.status = too_large ? StepStatus::kRejectedError : StepStatus::kAccepted;
  return result;
}

void EnergyDecayingIntegrator::Commit(const State& start, const Eigen::VectorXd& unknowns, double h,
                        const std::vector<NodeSchemeCoefficients>& coefficients, State* end) {
  const StepContext& ctx = builder_.context();
  *end = start;
  end->t = start.t + h;
  end->h_prev = h;
  end->history_steps = start.history_steps + 1;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeStep& s = (*ctx.nodes)[k];
    NodeState& n = end->nodes[k];
    n.x = s.x_f;
    n.R = s.R_f;
    n.v = s.v_f;
    n.w = s.w_f;
    n.a_prev2 = start.nodes[k].a_prev;
    n.alpha_prev2 = start.nodes[k].alpha_prev;
    n.a_prev = (s.v_f - s.v_i) / h;
    n.alpha_prev = (s.w_f - s.w_i) / h;
    end->peak_speed = std::max(end->peak_speed, n.v.norm());
    end->peak_spin = std::max(end->peak_spin, n.w.norm());
  }
  for (int k = 0; k < model_.num_variables(); ++k) end->q[k] = (*ctx.variables)[k].q_f;
  end->lambda = unknowns.tail(model_.num_multipliers());
  end->qdot = JointRates(model_, *end);
  end->qddot_prev = (end->qdot - start.qdot) / h;

  StepWork work;
  for (const auto& element : model_.elements()) element->AddStepWork(ctx, &work);
  double numerical = 0;
  for (const RigidBody* body : model_.rigid_bodies()) {
    const NodeStep& s = (*ctx.nodes)[body->node()];
    const NodeState& n = start.nodes[body->node()];
    const NodeSchemeCoefficients& c = coefficients[body->node()];
    const Vec3 dv = s.v_f - s.v_i, dw = s.w_f - s.w_i;
    numerical += c.alpha_translation * body->mass() * (dv - h * n.a_prev).dot(dv) +
                 c.alpha_rotation * (dw - h * n.alpha_prev).dot(body->inertia() * dw);
  }
  end->external_work += work.external;
  end->dissipated_physical += work.dissipated;
  end->dissipated_numerical += numerical;
}

}  // namespace flexmbd
