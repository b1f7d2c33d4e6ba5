#pragma once
/// @file
/// Lie-group generalized-alpha for the index-3 equations (Arnold and Bruls 2007; Bruls and Cardona 2010;
/// algorithm in REFERENCES section 3.2). The equations of motion and the constraints hold at the end of the
/// step; each node's increment (dx, theta), R_f = R_i Exp(theta), follows Newmark's relations
///   increment = h v_n + h^2 (1/2 - beta) a_n + h^2 beta a_{n+1},
///   v_{n+1} = v_n + h (1 - gamma) a_n + h gamma a_{n+1},
///   (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) vdot_{n+1} + alpha_f vdot_n,
/// with a the algorithmic acceleration and the coefficients set by rho_inf in [0, 1]. Angular velocities and
/// accelerations are in the node frame. The first step starts from consistent accelerations, measured over a
/// short energy-preserving step. A second option beside the energy-decaying default: it does not keep the books
/// of external work and dissipation (those outputs stay at zero).

#include <vector>

#include "flexmbd/solver/energy_decaying_integrator.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {

/// The coefficients of the scheme for one rho_inf and Newmark's relations between them.
struct GeneralizedAlphaCoefficients {
  explicit GeneralizedAlphaCoefficients(double rho_inf);
  double alpha_m, alpha_f, gamma, beta;

  /// a_{n+1} from the step's total increment.
  template <class V>
  V Acceleration(const V& increment, const V& v_n, const V& a_n, double h) const {
    return (increment - h * v_n - h * h * (0.5 - beta) * a_n) / (h * h * beta);
  }
  template <class V>
  V Velocity(const V& v_n, const V& a_n, const V& a_next, double h) const {
    return v_n + h * ((1.0 - gamma) * a_n + gamma * a_next);
  }
  /// vdot_{n+1}, the acceleration the equations of motion see.
  template <class V>
  V TrueAcceleration(const V& a_next, const V& a_n, const V& vdot_n) const {
    return ((1.0 - alpha_m) * a_next + alpha_m * a_n - alpha_f * vdot_n) / (1.0 - alpha_f);
  }
  /// The increment predicted on the assumption vdot_{n+1} = vdot_n.
  template <class V>
  V PredictedIncrement(const V& v_n, const V& a_n, const V& vdot_n, double h) const {
    const V a_next = (vdot_n - alpha_m * a_n) / (1.0 - alpha_m);
    return h * v_n + h * h * ((0.5 - beta) * a_n + beta * a_next);
  }
  /// First-order states (docs/theory.md, (S4)): the same relations one level down, the state x in the place of
  /// the velocity and its rate in the place of the acceleration. The algorithmic rate w_{n+1} from the step's
  /// increment x_{n+1} - x_n = h ((1 - gamma) w_n + gamma w_{n+1}):
  double AlgorithmicRate(double increment, double w_n, double h) const {
    return (increment / h - (1.0 - gamma) * w_n) / gamma;
  }
  /// The increment predicted on the assumption xdot_{n+1} = xdot_n.
  double PredictedStateIncrement(double w_n, double xdot_n, double h) const {
    return h * ((1.0 - gamma) * w_n + gamma * (xdot_n - alpha_m * w_n) / (1.0 - alpha_m));
  }
  /// d xdot / d increment
  double state_rate_rate(double h) const { return (1.0 - alpha_m) / (h * gamma * (1.0 - alpha_f)); }
  /// d v / d increment
  double velocity_rate(double h) const { return gamma / (h * beta); }
  /// d vdot / d increment
  double acceleration_rate(double h) const { return (1.0 - alpha_m) / (h * h * beta * (1.0 - alpha_f)); }
};

class GeneralizedAlphaIntegrator : public TimeIntegrator {
 public:
  GeneralizedAlphaIntegrator(const Model& model, SparseSystem* system);

  StepResult Step(const State& start, double h, State* end) override;
  const StepContext& last_context() const override { return builder_.context(); }

 private:
  // The start state with accelerations measured over a short energy-preserving step (first step only).
  State WithInitialAccelerations(const State& start, double h);
  // Sets the end velocities and accelerations of the current context from the total increments.
  void FillKinematics(const State& start, const std::vector<Vec6>& increments, const Eigen::VectorXd& dq,
                      const Eigen::VectorXd& dx, double h);
  // The end state once Newton has converged.
  void Commit(const State& start, const State& iterate, const std::vector<Vec6>& increments,
              const Eigen::VectorXd& dq, const Eigen::VectorXd& dx, double h, State* end) const;

  const Model& model_;
  SparseSystem* system_;
  StepContextBuilder builder_;
  GeneralizedAlphaCoefficients c_;
  EnergyDecayingIntegrator starter_;  ///< energy preserving here: the model does not ask for decay
};

}  // namespace flexmbd
