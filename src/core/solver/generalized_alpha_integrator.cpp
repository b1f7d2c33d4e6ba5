#include "flexmbd/solver/generalized_alpha_integrator.hpp"

#include <algorithm>
#include <limits>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/joint_rates.hpp"
#include "flexmbd/solver/sparse_system.hpp"

#include "drive_rows.hpp"

namespace flexmbd {

GeneralizedAlphaCoefficients::GeneralizedAlphaCoefficients(double rho_inf)
    : alpha_m((2.0 * rho_inf - 1.0) / (rho_inf + 1.0)),
      alpha_f(rho_inf / (rho_inf + 1.0)),
      gamma(0.5 + alpha_f - alpha_m),
      beta(0.25 * (gamma + 0.5) * (gamma + 0.5)) {}

GeneralizedAlphaIntegrator::GeneralizedAlphaIntegrator(const Model& model, SparseSystem* system)
    : model_(model), system_(system), builder_(model), c_(model.solver().rho_inf), starter_(model, system) {}

State GeneralizedAlphaIntegrator::WithInitialAccelerations(const State& start, double h) {
  // The mean acceleration over [0, eps] is the acceleration at eps/2: an O(eps) error in the start values,
  // which keeps the scheme second order (Arnold and Bruls 2007) while eps = 1e-3 h keeps the system well
  // conditioned.
  constexpr double kStarterFraction = 1.0e-3;
  State probe;
  const StepResult result = starter_.Step(start, kStarterFraction * h, &probe);
  State with = start;
  if (result.status != StepStatus::kAccepted) return with;  // zero start accelerations; Newton will tell
  for (int k = 0; k < model_.num_nodes(); ++k) {
    NodeState& n = with.nodes[k];
    n.a_prev = n.a_alg = probe.nodes[k].a_prev;
    n.alpha_prev = n.alpha_alg = probe.nodes[k].alpha_prev;
  }
  with.qddot_prev = with.qacc_alg = probe.qddot_prev;
  with.element_state_rates = with.element_state_rates_alg = probe.element_state_rates;
  return with;
}

namespace {
// Variables' algorithmic and true accelerations, zero before the first step.
Eigen::VectorXd OrZero(const Eigen::VectorXd& v, int size) {
  return v.size() == size ? v : Eigen::VectorXd::Zero(size);
}
}  // namespace

void GeneralizedAlphaIntegrator::FillKinematics(const State& start, const std::vector<Vec6>& increments,
                                                const Eigen::VectorXd& dq, const Eigen::VectorXd& dx, double h) {
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeState& n = start.nodes[k];
    NodeStep& s = builder_.nodes()[k];
    const Vec3 a = c_.Acceleration<Vec3>(increments[k].head<3>(), n.v, n.a_alg, h);
    const Vec3 alpha = c_.Acceleration<Vec3>(increments[k].tail<3>(), n.w, n.alpha_alg, h);
    s.v_f = c_.Velocity<Vec3>(n.v, n.a_alg, a, h);
    s.w_f = c_.Velocity<Vec3>(n.w, n.alpha_alg, alpha, h);
    s.vdot_f = c_.TrueAcceleration<Vec3>(a, n.a_alg, n.a_prev);
    s.wdot_f = c_.TrueAcceleration<Vec3>(alpha, n.alpha_alg, n.alpha_prev);
    s.v_i = n.v;
    s.w_i = n.w;
    s.dvf_ddx = s.dwf_dtheta = c_.velocity_rate(h);
    s.dacc = c_.acceleration_rate(h);
  }
  const int nv = model_.num_variables();
  const Eigen::VectorXd acc = OrZero(start.qacc_alg, nv);
  for (int k = 0; k < nv; ++k) {
    VariableStep& v = builder_.variables()[k];
    v.qdot_f = c_.Velocity<double>(start.qdot[k], acc[k], c_.Acceleration<double>(dq[k], start.qdot[k], acc[k], h), h);
    v.dqdotf_dq = c_.velocity_rate(h);
  }
  for (int k = 0; k < model_.num_element_states(); ++k) {
    ElementStateStep& x = builder_.element_states()[k];
    const double w_n = start.element_state_rates_alg[k];
    x.rate = c_.TrueAcceleration<double>(c_.AlgorithmicRate(dx[k], w_n, h), w_n, start.element_state_rates[k]);
    x.drate = c_.state_rate_rate(h);
  }
}

StepResult GeneralizedAlphaIntegrator::Step(const State& given_start, double h, State* end) {
  const State start = given_start.history_steps == 0 ? WithInitialAccelerations(given_start, h) : given_start;
  const int nv = model_.num_variables();
  const Eigen::VectorXd q_acc = OrZero(start.qacc_alg, nv), q_ddot = OrZero(start.qddot_prev, nv);
  // Predictor; the iterate holds the end configuration and is moved by each Newton increment.
  State iterate = start;
  std::vector<Vec6> increments(model_.num_nodes());
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeState& n = start.nodes[k];
    increments[k] << c_.PredictedIncrement<Vec3>(n.v, n.a_alg, n.a_prev, h),
        c_.PredictedIncrement<Vec3>(n.w, n.alpha_alg, n.alpha_prev, h);
    iterate.nodes[k].x = n.x + increments[k].head<3>();
    iterate.nodes[k].R = n.R * Exp(increments[k].tail<3>());
  }
  Eigen::VectorXd dq(nv);
  for (int k = 0; k < nv; ++k) dq[k] = c_.PredictedIncrement<double>(start.qdot[k], q_acc[k], q_ddot[k], h);
  iterate.q = start.q + dq;
  const int ns = model_.num_element_states();
  Eigen::VectorXd dx(ns);
  for (int k = 0; k < ns; ++k) {
    dx[k] = c_.PredictedStateIncrement(start.element_state_rates_alg[k], start.element_state_rates[k], h);
  }
  iterate.element_states = start.element_states + dx;
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model_.num_unknowns());
  unknowns.tail(model_.num_multipliers()) = start.lambda;
  const double t_f = start.t + h;

  StepResult result;
  result.newton = SolveNewton(
      model_, system_, model_.solver().tol, model_.solver().max_iterations, NoiseFloor(model_, start),
      [&](int iteration, bool with_tangent) -> const StepContext& {
        builder_.set_geometric_stiffness(with_tangent && iteration > 1);
        const StepContext& ctx = builder_.EndPoint(iterate, unknowns, t_f, h);
        FillKinematics(start, increments, dq, dx, h);
        return ctx;
      },
      [&](const Eigen::VectorXd& increment) {
        double reference = 0;
        for (int k = 0; k < model_.num_nodes(); ++k) {
          NodeState& n = iterate.nodes[k];
          n.x += increment.segment<3>(model_.node_unknown(k));
          n.R = n.R * Exp(increment.segment<3>(model_.node_unknown(k) + 3));
          increments[k] << n.x - start.nodes[k].x, Log(start.nodes[k].R.transpose() * n.R);
          reference = std::max(reference, increments[k].cwiseAbs().maxCoeff());
        }
        for (int k = 0; k < nv; ++k) dq[k] += increment[model_.variable_unknown(k)];
        iterate.q = start.q + dq;
        dx += increment.segment(model_.element_state_unknown(0), ns);
        iterate.element_states = start.element_states + dx;
        if (ns > 0) reference = std::max(reference, dx.cwiseAbs().maxCoeff());
        unknowns.tail(model_.num_multipliers()) += increment.tail(model_.num_multipliers());
        return (nv > 0 ? std::max(reference, dq.cwiseAbs().maxCoeff()) : reference) + kMotionFloor;
      });
  system_->set_factorisation_key(std::numeric_limits<double>::quiet_NaN());  // not a reusable dynamic tangent
  if (result.newton.singular || !result.newton.converged) {
    result.status = result.newton.singular ? StepStatus::kSingularMatrix : StepStatus::kNewtonDiverged;
    return result;
  }
  iterate.lambda = unknowns.tail(model_.num_multipliers());
  builder_.EndPoint(iterate, unknowns, t_f, h);
  FillKinematics(start, increments, dq, dx, h);
  Commit(start, iterate, increments, dq, dx, h, end);
  result.error = EstimateLocalError(model_, *end);
  const bool too_large = model_.solver().adaptive && result.error.error > 1.0;
  result.status = too_large ? StepStatus::kRejectedError : StepStatus::kAccepted;
  return result;
}

void GeneralizedAlphaIntegrator::Commit(const State& start, const State& iterate, const std::vector<Vec6>& increments,
                                        const Eigen::VectorXd& dq, const Eigen::VectorXd& dx, double h,
                                        State* end) const {
  *end = iterate;
  end->t = start.t + h;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeState& n = start.nodes[k];
    const NodeStep& s = builder_.context().nodes->at(k);
    NodeState& e = end->nodes[k];
    e.v = s.v_f;
    e.w = s.w_f;
    e.a_alg = c_.Acceleration<Vec3>(increments[k].head<3>(), n.v, n.a_alg, h);
    e.alpha_alg = c_.Acceleration<Vec3>(increments[k].tail<3>(), n.w, n.alpha_alg, h);
    e.a_prev2 = n.a_prev;
    e.alpha_prev2 = n.alpha_prev;
    e.a_prev = s.vdot_f;
    e.alpha_prev = s.wdot_f;
  }
  const int nv = model_.num_variables();
  const Eigen::VectorXd acc = OrZero(start.qacc_alg, nv), qddot = OrZero(start.qddot_prev, nv);
  end->qacc_alg.resize(nv);
  end->qddot_prev.resize(nv);
  for (int k = 0; k < nv; ++k) {
    end->qacc_alg[k] = c_.Acceleration<double>(dq[k], start.qdot[k], acc[k], h);
    end->qddot_prev[k] = c_.TrueAcceleration<double>(end->qacc_alg[k], acc[k], qddot[k]);
  }
  end->qdot = JointRates(model_, *end);
  for (int k = 0; k < model_.num_element_states(); ++k) {
    end->element_state_rates_alg[k] = c_.AlgorithmicRate(dx[k], start.element_state_rates_alg[k], h);
    end->element_state_rates[k] = (*builder_.context().element_states)[k].rate;
  }
  RecordStepHistory(start, h, end);
  end->drive_rates = DriveRates(model_, *end, RateSide::kBefore);
}

}  // namespace flexmbd
