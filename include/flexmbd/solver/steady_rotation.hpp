#pragma once
/// @file
/// Steady rotation (relative equilibrium) of a system whose spinning joint turns at a constant rate, and
/// eigen-analysis about it (docs/theory.md, "Steady rotation", eqs. (R1)-(R4)). The rotating part turns rigidly
/// about a fixed axis at the speed Omega; in the frame turning with it the configuration is still, stretched by
/// the centrifugal forces and deflected by gravity and steady loads.
///
/// @code
///   const SteadyRotation spin = SteadyRotationOf(model, model.initial_state());
///   const SteadyResult steady = SolveSteadyRotation(model, model.initial_state(), spin);
///   const EigenResult modes = EigenAnalysisAboutSteadyRotation(model, steady.state, spin, EigenOptions{});
/// @endcode

#include <Eigen/Core>
#include <vector>

#include "flexmbd/math/so3.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/model/state.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"

namespace flexmbd {

/// The rigid rotation of the spinning part of a model: which nodes turn, about which axis, how fast.
struct SteadyRotation {
  Vec3 axis_W = Vec3::UnitZ();  ///< unit spin axis in W
  Vec3 center_W = Vec3::Zero(); ///< a point of the spin axis in W [m]
  double speed = 0.0;           ///< Omega [rad/s], about axis_W
  std::vector<bool> rotating;   ///< per node: turns with the spin (else at rest)
  int spinning_variable = -1;   ///< the joint variable that spins (its rate is Omega)
  double variable_sense = 1.0;  ///< that variable's rate per unit Omega: +-1, by the sense of its joint axis
};

/// The steady rotation a state's velocities describe: every node either at rest or turning rigidly about one
/// fixed axis, and exactly one joint variable with a non-zero rate (the hub). Throws ConfigError naming the
/// model's source and `joints.*.initial.velocity` when that is not so (no spinning joint, several, or node
/// velocities that are no rigid rotation).
SteadyRotation SteadyRotationOf(const Model& model, const State& state);

/// The same rotation `factor` times as fast (a fan plot's speed).
SteadyRotation ScaleSpeed(const SteadyRotation& rotation, double factor);

/// The state's configuration in steady rotation (theory (R1)): v = Omega x (x - c), w = R^T Omega,
/// v' = Omega x v and w' = 0 on turning nodes, zero on the others; the spinning variable at its rate, every
/// other joint rate and acceleration zero.
State WithSteadyMotion(const Model& model, const State& state, const SteadyRotation& rotation);

/// Outcome of SolveSteadyRotation.
struct SteadyResult {
  State state;          ///< the steady configuration with its motion (WithSteadyMotion) and multipliers
  int iterations = 0;   ///< Newton iterations over all speed steps
  double hub_effort = 0.0;  ///< torque (or force) that holds the spinning variable's rate [N m or N]; 0 if driven
};

/// Solves the equations of motion with the motion of (R1) for the configuration and multipliers (theory (R2)),
/// from the configuration of `start`, raising the speed in solver.load_steps equal steps. The spinning
/// variable's angle is held where `start` has it (a motor holding its rate; a drive on it holds it instead).
/// Throws SolverError naming the worst unknown if Newton does not converge within solver.max_iterations.
SteadyResult SolveSteadyRotation(const Model& model, const State& start, const SteadyRotation& rotation);

/// Eigen-analysis about a steady state (theory (R3)-(R4)): the equations linearised about it with the rate of
/// the spinning variable held (a governed rotor), so that the rigid rotation about the spin axis is one
/// rigid-body mode of zero frequency, listed first, and the rest are the modes at constant speed.
EigenResult EigenAnalysisAboutSteadyRotation(const Model& model, const State& steady, const SteadyRotation& rotation,
                                             const EigenOptions& options);

/// A fan plot over rotor speed: for each factor, the steady state at `factor` times the speed of `rotation`
/// (solved from `start`'s configuration) and the eigen-analysis about it; modes tracked as by EigenSweep.
std::vector<SweepPoint> SteadyRotationSweep(const Model& model, const State& start, const SteadyRotation& rotation,
                                            const std::vector<double>& factors, const EigenOptions& options);

}  // namespace flexmbd
