#pragma once
/// @file
/// Which rigid stops a joint that touches them rests on, where no step has decided it: a static analysis, and an
/// eigen-analysis about the model's initial state (docs/theory.md, (C2a) and "Eigen-analysis").

namespace flexmbd {

class Model;
struct State;

/// Closes the open rigid stops whose gap at *state is at most `round_off` (touched: the joint is on the stop).
void CloseTouchedRigidStops(const Model& model, double round_off, State* state);

/// The state with each rigid stop it touches closed where the motion released at it presses the joint on the stop
/// (a contact force >= 0 in its consistent accelerations and multipliers), and open where it would pull: the modes a
/// step from the state takes, and those a static analysis gives a stop touched at its equilibrium. Throws
/// SolverError where the consistent motion cannot be solved for (WithConsistentMotion).
State WithTouchedStopsDecided(const Model& model, const State& state);

}  // namespace flexmbd
