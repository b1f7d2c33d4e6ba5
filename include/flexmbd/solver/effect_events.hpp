#pragma once
/// @file
/// The mode changes of effects with modes during a run (contacts begun and ended, sticking begun and ended)
/// and their report as intervals.

#include <string>
#include <vector>

namespace flexmbd {

class Model;
struct State;

/// One mode change in an accepted step, or at the start of a dynamic run from the model's initial mode (a contact
/// that a static analysis closed).
struct EffectEvent {
  double t = 0;     ///< when the new mode began: the step's start if the step was solved in it, else its end [s]
  int effect = -1;  ///< index into Model::modal_effects()
  int from = 0, to = 0;
};

/// One line (without newline) per stop and frictional joint: the intervals in contact (or sticking), the last one
/// closed at the state's time if still open, e.g. "stop B1 upper: 2 contact interval(s) [0.51, 0.52] [0.93, 1] s"; for
/// friction also the sticking threshold v0 in force and the energy dissipated. After a static analysis
/// (solver.analysis: static) each stop is closed, with its contact force, or open, with its gap, and friction
/// is left out: "stop slide upper: closed in the static equilibrium, contact force 9.81 N".
std::vector<std::string> DescribeEffectIntervals(const Model& model, const std::vector<EffectEvent>& events,
                                                 const State& state);

}  // namespace flexmbd
