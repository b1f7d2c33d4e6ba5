#pragma once
/// @file
/// The rates a dynamic run starts with from a static equilibrium (docs/theory.md, "Rates of a static start"
/// (K4)): every drive at its rate f'(t), everything else at rest relative to what carries it.

namespace flexmbd {

class Model;
struct State;

/// Gives the static equilibrium `state` (every rate zero) the rates (K4): the velocities that meet every
/// constraint row at its rate (a drive's row at f'(t), the others at zero) and, within those, leave every undriven
/// variable and spherical joint at rest and every beam moving rigidly, in least squares where loops make them
/// conflict. Leaves `state` untouched when no drive moves at state->t.
void SetStaticStartRates(const Model& model, State* state);

}  // namespace flexmbd
