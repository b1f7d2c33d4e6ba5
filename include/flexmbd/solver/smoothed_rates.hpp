#pragma once
// The rates of an accepted state of the energy-consistent schemes without the trapezoidal relation's alternating
// mode: what the eigen-analysis at a time of a run linearises about (docs/theory.md (E10)).

#include "flexmbd/model/state.hpp"

namespace flexmbd {

/// `end` with its node velocities and angular velocities, joint rates and element state rates replaced by the
/// mean rates of its last three steps extrapolated to its time by the parabola through their midpoints; a node's
/// mean rates are taken as the constant body twist of a screw motion over each step, so that a steady rotation
/// gives its rates exactly. Needs three steps since the start or the last jump (State::history_steps >= 3);
/// otherwise `end` is returned unchanged.
State WithSmoothedRates(const State& end);

}  // namespace flexmbd
