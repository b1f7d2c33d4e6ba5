#pragma once
/// @file
/// The first step of an adaptive run, chosen by the local error estimate instead of taken on trust
/// (docs/theory.md, (T12), "First step").

#include "flexmbd/model/state.hpp"
#include "flexmbd/solver/step_controller.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {

/// Takes trial steps of size h from `start` (which stays as it is) until the first error estimate, three steps
/// on; while that estimate exceeds the tolerance, shrinks h by the controller's law and tries again. A Newton
/// failure or a singular matrix shrinks h as the controller would. A stop or friction event is resolved as the run
/// resolves it (the step redone at the size the effect asks for), and the estimate then comes three steps after
/// it. Every trial step is booked with `controller`. Returns the size to start the run with, never below dt_min.
double ChooseStartingStep(TimeIntegrator* integrator, const State& start, double h, double dt_min,
                          StepController* controller);

}  // namespace flexmbd
