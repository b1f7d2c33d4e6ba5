#pragma once
/// @file
/// The first output sample of a dynamic run. A state gives positions and rates but not the forces its motion asks for
/// (the multipliers of the drives and joints, the friction, the dampers' and the air's rate terms), which a step
/// solves for: the sample takes those of a step of vanishing length from it (docs/config.md, "Output").

#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {

class Model;
struct State;

/// The sample at `state`, the start of a run whose first step is h [s], with the mean forces of steps of 1e-3 h and
/// 2e-3 h from it extrapolated to a step of length 0; where such a step does not converge, with the state's own
/// multipliers.
OutputSample StartSample(const Model& model, const State& state, double h);

}  // namespace flexmbd
