#pragma once
/// @file
/// State: the minimal copyable set that fixes the future of a run. Copying a State undoes a rejected step.

#include <array>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "flexmbd/math/so3.hpp"

namespace flexmbd {

/// Kinematic state of one node (3 displacements and a finite rotation).
struct NodeState {
  Vec3 x = Vec3::Zero();            ///< position in W [m]
  Mat3 R = Mat3::Identity();        ///< orientation R_WN
  Vec3 v = Vec3::Zero();            ///< velocity in W [m/s]
  Vec3 w = Vec3::Zero();            ///< angular velocity, in the node frame [rad/s]
  Vec3 a_prev = Vec3::Zero();       ///< linear acceleration of the last accepted step, in W [m/s^2]: its mean
                                    ///< turned with the node through the step (energy-consistent schemes, (T3b))
                                    ///< or its end value (generalized-alpha)
  Vec3 alpha_prev = Vec3::Zero();   ///< angular acceleration of the last accepted step, node frame [rad/s^2]
  Vec3 a_prev2 = Vec3::Zero();      ///< a_prev of the step before (turned once more, (T3b)) [m/s^2]
  Vec3 alpha_prev2 = Vec3::Zero();  ///< alpha_prev of the step before [rad/s^2]
  /// Mean velocities (x_f - x_i)/h and mean angular velocities (rotation vector of the step in W, over h) of the
  /// last three accepted steps, newest first [m/s, rad/s]: the local error estimate's history (T12).
  std::array<Vec3, 3> mean_v = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  std::array<Vec3, 3> mean_w = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  Vec3 a_alg = Vec3::Zero();        ///< generalized-alpha algorithmic linear acceleration [m/s^2]
  Vec3 alpha_alg = Vec3::Zero();    ///< generalized-alpha algorithmic angular acceleration [rad/s^2]
};

/// The mode and memory of one effect with modes (a stop, a frictional joint).
struct EffectState {
  int mode = 0;            ///< stops: 0 open, 1 in contact, 2 retracted; friction: 0 sliding, 1 sticking
  double reference = 0.0;  ///< elastic stops: approach speed when the contact began, rigid stops: the fastest
                           ///< approach speed at an impact [m/s]; friction: the
                           ///< largest slip speed seen [m/s]
  double work = 0.0;       ///< energy this effect dissipated since t = 0 [J]
  long events = 0;         ///< contacts begun (stops), sticking episodes begun (friction)
  /// Friction: the sticking force of the last accepted step if it began stuck and stayed stuck (a steady stick,
  /// whose force locates a breakaway, docs/theory.md (F3')) [N m or N]; NaN otherwise.
  double steady_force = std::numeric_limits<double>::quiet_NaN();
  /// Friction: the excess |force| - mu_s rho N of the steady stick's step before the last, when that step was one
  /// too; with steady_force it gives the trend the last force departed from (F3') [N m or N]; NaN otherwise.
  double steady_excess_before = std::numeric_limits<double>::quiet_NaN();
  /// Friction: the joint sticks in the step being solved (or that led to this state) and its sticking row
  /// repeats the other constraint rows, which then hold it: the row is left out and friction applies no force
  /// (docs/theory.md (F7)).
  bool held_by_constraints = false;
  /// The velocity projection after a step that led here held this effect at rest in its mode (an effect whose
  /// ComesToRest says so: a rigid contact that came to rest, docs/theory.md (C2a')), and it has kept that mode since
  /// (the integrator sets it and clears it where the mode changes): a rigid stop's contact steps from such a start
  /// close the gap the contact began with.
  bool held_at_rest = false;
};

/// What a controller commands on one joint variable (Simulation::SetEffort, SetSetpoint; docs/theory.md,
/// "Commands"). It acts from the next step on and holds until changed.
struct VariableCommand {
  double effort = 0.0;         ///< generalised force applied on the variable [N m or N]
  bool has_setpoint = false;   ///< a driven variable follows `setpoint` instead of its drive's law
  double setpoint = 0.0;       ///< [rad or m]
  double time_constant = 0.0;  ///< of the first-order lag by which the drive follows the set-point [s], > 0
};

/// Everything that changes during a run.
struct State {
  double t = 0.0;                   ///< time [s]
  std::vector<NodeState> nodes;     ///< (num_nodes)
  Eigen::VectorXd q;                ///< joint relative-motion variables [rad or m] (num_variables)
  Eigen::VectorXd qdot;             ///< their rates [rad/s or m/s] (num_variables)
  Eigen::VectorXd qddot_prev;       ///< rate of change of qdot over the last accepted step (num_variables)
  Eigen::VectorXd qddot_prev2;      ///< qddot_prev of the step before
  Eigen::VectorXd dq_prev;          ///< increment of each variable over the last accepted step
  Eigen::VectorXd qacc_alg;         ///< generalized-alpha algorithmic accelerations of the variables
  Eigen::VectorXd lambda;           ///< constraint multipliers [N, N m] (num_multipliers)
  Eigen::VectorXd element_states;      ///< the elements' own states (Model::num_element_states(); element units)
  /// Their rates: the mean rate of the last step (energy-consistent schemes, the midpoint rule (S2)), the end
  /// rate (generalized-alpha), zero after a static analysis.
  Eigen::VectorXd element_state_rates;
  Eigen::VectorXd element_state_rates_alg;  ///< generalized-alpha algorithmic rates of the element states
  std::vector<EffectState> effects; ///< per effect with modes (Model::modal_effects())
  std::vector<VariableCommand> commands;  ///< per joint variable (num_variables)
  /// Per joint variable, the rate its drive imposed at the end of the last accepted step (at the start of a run, its
  /// law's rate there, which the initial rates follow); a step that starts where the drive imposes another rate (a
  /// kink of its law, a new set-point) starts with a jump of that rate (docs/theory.md, "Jumps of a drive's rate")
  /// [rad/s or m/s]. Zero on variables without a drive.
  Eigen::VectorXd drive_rates;
  /// Per element (Model::elements()), what it keeps of past steps (Element::history_size(); mostly empty).
  std::vector<Eigen::VectorXd> element_history;
  int history_steps = 0;            ///< accepted steps since the start or the last jump in the motion (T12)
  double h_prev = 0.0;              ///< size of the last accepted step [s]
  std::array<double, 3> recent_h = {0.0, 0.0, 0.0};  ///< sizes of the last three accepted steps, newest first [s]
  std::array<Eigen::VectorXd, 3> mean_qdot;          ///< dq / h of the last three accepted steps, newest first
  std::array<Eigen::VectorXd, 3> mean_state_rate;    ///< the same for the element states
  double peak_speed = 0.0;          ///< largest node speed so far [m/s]: scales of the local error test
  double peak_spin = 0.0;           ///< largest node angular speed so far [rad/s]
  Eigen::VectorXd peak_joint_rate;  ///< largest |qdot| of each joint variable so far [rad/s or m/s] (num_variables)
  Eigen::VectorXd peak_state_rate;  ///< largest |mean rate| of each element state so far (element units per s)
  double external_work = 0.0;       ///< work of applied loads, drives and commanded efforts since t = 0 [J]
  double dissipated_physical = 0.0; ///< energy dissipated by dampers, friction, stop and beam damping since t = 0 [J]
  double dissipated_numerical = 0.0;///< energy removed by the integrator's dissipation since t = 0 [J]
};

}  // namespace flexmbd
