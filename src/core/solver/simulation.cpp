#include "flexmbd/solver/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "flexmbd/common/error.hpp"
#include "flexmbd/solver/smoothed_rates.hpp"
#include "flexmbd/solver/start_sample.hpp"
#include "flexmbd/solver/starting_step.hpp"
#include "flexmbd/solver/static_start_rates.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "flexmbd/solver/step_to_landing.hpp"

namespace flexmbd {
namespace {
// Times closer than this fraction of a step are the same instant (guards the end of the run and sample times
// against round-off in sums of step sizes).
constexpr double kTimeEpsilon = 1.0e-9;

std::string FormatCommand(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// What a user can try when the step size fell below dt_min, by the reason the last attempt failed.
const char* WhatToTry(StepStatus status, bool adaptive) {
  switch (status) {
    case StepStatus::kRejectedError:
      return "try a larger solver.error_tol or solver.error_floor, or a smaller solver.dt_min";
    case StepStatus::kRejectedEvent:
      // With fixed steps the events ask for what the motion needs, an elastic stop's contact steps of about
      // 1 / steps_per_contact of its impact (C6) for one, which a dt_min can forbid: the fixed-step hint below.
      if (!adaptive) break;
      return "a stop or friction event could not be stepped across, which is a defect of flexmbd: please report "
             "the model; meanwhile try solver.adaptive: false with a smaller solver.dt, or an elastic stop";
    case StepStatus::kNewtonDiverged:
      return "try a smaller solver.dt, a larger solver.tol, or check that the joints' initial positions and "
             "drives agree";
    case StepStatus::kSingularMatrix:
      return "check for constraints that repeat each other (a closed loop of joints, a drive on a fixed "
             "motion) and for bodies without mass or inertia";
    case StepStatus::kAccepted:
      break;
  }
  // An accepted step whose next step fell below dt_min was held back by a stop or friction event's step limit, or
  // (fixed steps) an event asked for a step below it. Fixed steps far too large for the motion leave it
  // unresolved, and the events after it shrink without end.
  if (!adaptive) return "try a smaller solver.dt (fixed steps may leave the motion unresolved), adaptive steps, "
                        "or a smaller solver.dt_min";
  return "try a smaller solver.dt_min";
}

}  // namespace

Simulation::Simulation(const Model& model)
    : model_(model),
      state_(model.initial_state()),
      system_(model),
      integrator_(MakeTimeIntegrator(model, &system_)),
      controller_(model.solver()) {}

OutputSample Simulation::SampleAtState(double dt, int iterations) {
  StepContextBuilder builder(model_);
  return MakeSample(model_, state_, builder.AtState(state_), dt, iterations);
}

void Simulation::Fail(const char* what, double h, const StepResult& last) const {
  std::ostringstream msg;
  msg << what << " at t = " << state_.t << " s with step " << h << " s (dt_min = " << model_.solver().dt_min
      << " s); last attempt: " << StepStatusName(last.status);
  if (last.newton.worst_unknown >= 0) {
    msg << "; worst residual at " << model_.DescribeUnknown(last.newton.worst_unknown) << " (force "
        << last.newton.force_residual << " relative, constraint " << last.newton.constraint_residual << ")";
  }
  msg << "; " << WhatToTry(last.status, model_.solver().adaptive);
  throw SolverError(msg.str());
}

StaticResult Simulation::SolveStaticEquilibrium() {
  const StaticResult result = SolveStatic(model_, &system_, &state_);
  if (!result.converged) throw SolverError(DescribeStaticFailure(model_, result));
  return result;
}

void Simulation::SolveStaticStart() {
  SolveStaticEquilibrium();
  SetStaticStartRates(model_, &state_);
}

void Simulation::Run(const SampleSink& sink) { Run(sink, {}, nullptr); }

void Simulation::Run(const SampleSink& sink, const std::vector<double>& instants, const StateSink& at_instant) {
  const SolverSpec& solver = model_.solver();
  if (solver.analysis == SolverSpec::Analysis::kStatic) {
    const StaticResult result = SolveStaticEquilibrium();
    sink(SampleAtState(0.0, result.iterations));
    return;
  }
  if (solver.static_first) SolveStaticStart();
  Begin(sink);
  // Generalized-alpha damps the alternating velocity mode that the energy-consistent schemes' end rates carry.
  const bool rates_alternate = solver.integrator != SolverSpec::Integrator::kGeneralizedAlpha;
  for (double t : instants) {
    AdvanceTo(t, t, sink);  // with t as the end, the last step lands on it
    if (Stopped()) return;
    at_instant(rates_alternate ? WithSmoothedRates(state_) : state_);
  }
  AdvanceTo(solver.t_end, solver.t_end, sink);
}

void Simulation::SetEffort(int variable, double effort) {
  CheckCommand(variable, "effort", effort);
  state_.commands[variable].effort = effort;
}

void Simulation::SetSetpoint(int variable, double setpoint, double time_constant) {
  CheckCommand(variable, "set-point", setpoint);
  const std::string& name = model_.variable_names()[variable];
  if (!model_.driven(variable)) {
    throw ConfigError("set-point for joint variable '" + name +
                      "', which has no drive; expected a set-point for a driven variable");
  }
  if (!(time_constant > 0.0 && std::isfinite(time_constant))) {
    throw ConfigError("set-point for joint variable '" + name + "': time constant " + FormatCommand(time_constant) +
                      " is not a finite number > 0 [s]");
  }
  VariableCommand& command = state_.commands[variable];
  const bool new_pace = !command.has_setpoint || command.setpoint != setpoint || command.time_constant != time_constant;
  command.has_setpoint = true;
  command.setpoint = setpoint;
  command.time_constant = time_constant;
  const SolverSpec& solver = model_.solver();
  if (new_pace && solver.adaptive) {
    // The lag's rate jumps here, and the error estimate restarts after it (docs/theory.md, "Commands"): until it is
    // back, the steps are those it would allow the lag, whose local error h^3 |q'''| / 12 = h^3 |q'| / (12 tau^2)
    // (T12) is error_tol h |q'| at h = tau sqrt(12 error_tol).
    const double resolving = time_constant * std::sqrt(12.0 * solver.error_tol);
    h_ = std::min(h_, resolving);
    controller_.Restart(resolving);
  }
}

void Simulation::CheckCommand(int variable, const char* what, double value) const {
  if (variable < 0 || variable >= model_.num_variables()) {
    throw ConfigError(std::string(what) + " for joint variable " + std::to_string(variable) + ": no such variable; "
                      "expected 0 <= variable < " + std::to_string(model_.num_variables()));
  }
  if (!std::isfinite(value)) {
    throw ConfigError(std::string(what) + " for joint variable '" + model_.variable_names()[variable] + "': " +
                      FormatCommand(value) + " is not a finite number");
  }
}

StepResult Simulation::TryStep(double h) {
  State end;
  const StepResult result = integrator_->Step(state_, h, &end);
  if (result.status != StepStatus::kAccepted) return result;
  // A step solved in its end mode (a breakaway, a contact begun or left within the step) has it from its start;
  // a mode taken at its end (sticking below v0, a retraction) holds from its end.
  const std::vector<EffectState>& solved = *integrator_->last_context().effects;
  for (size_t k = 0; k < end.effects.size(); ++k) {
    const int from = state_.effects[k].mode, to = end.effects[k].mode;
    if (from != to) effect_events_.push_back({solved[k].mode == to ? state_.t : end.t, static_cast<int>(k), from, to});
  }
  state_ = std::move(end);
  return result;
}

void Simulation::Integrate(double t_end, const SampleSink& sink) {
  Begin(sink);
  AdvanceTo(t_end, t_end, sink);
}

void Simulation::Begin(const SampleSink& sink) {
  // A mode the run starts in other than the model's initial one (a contact a static analysis closed) is an interval
  // that begins at the start: the intervals count from the initial modes.
  const std::vector<EffectState>& initial = model_.initial_state().effects;
  for (size_t k = 0; k < state_.effects.size(); ++k) {
    const int from = initial[k].mode, to = state_.effects[k].mode;
    if (from != to) effect_events_.push_back({state_.t, static_cast<int>(k), from, to});
  }
  const SolverSpec& solver = model_.solver();
  h_ = std::min(solver.dt, solver.dt_max);
  if (solver.adaptive) {
    h_ = ChooseStartingStep(integrator_.get(), state_, h_, solver.dt_min, &controller_);
    controller_.Start(h_);
  }
  previous_ = StartSample(model_, state_, h_);
  sink(previous_);
  next_sample_ = 1;
  t_start_ = state_.t;
}

void Simulation::AdvanceTo(double t_until, double t_end, const SampleSink& sink) {
  const SolverSpec& solver = model_.solver();
  const double sample_period = model_.output().rate_hz > 0 ? 1.0 / model_.output().rate_hz : 0.0;
  // Each call ends on an accepted step, so a call starts as after one, and a run split into calls (a node's pauses)
  // takes the steps of a run in one.
  bool rejected = false;
  while (state_.t < std::min(t_until, t_end) - kTimeEpsilon * h_ && !Stopped()) {
    // Steps land on t_end and on every breakpoint of the time functions before it, never across one, except one
    // closer than dt_min: the step after a landing grows from the landing's size, and a table's 1e-9 s edge landed on
    // left the run below dt_min. The run's last steps share the time left; a breakpoint or an instant the run stops at
    // before its end (at_times) is reached by one step, so that the state an eigen-analysis takes there stays as it
    // was.
    const std::vector<double>& breakpoints = model_.breakpoints();
    const auto next_breakpoint = std::upper_bound(breakpoints.begin(), breakpoints.end(),
                                                  state_.t + std::max(kTimeEpsilon * h_, solver.dt_min));
    const bool to_breakpoint = next_breakpoint != breakpoints.end() && *next_breakpoint < t_end;
    const double t_land = to_breakpoint ? *next_breakpoint : t_end;
    const int window = to_breakpoint || t_end < solver.t_end ? 1 : kLastSteps;
    const double h = StepToLanding(std::min(h_, solver.dt_max), t_land - state_.t, window, rejected);
    const StepResult result = TryStep(h);
    rejected = result.status != StepStatus::kAccepted;
    const double h_next = controller_.Next(h, result);
    // Past a breakpoint the motion's derivatives jump: the error estimate and the scheme's dissipation restart their
    // history there, as after an impact.
    if (result.status == StepStatus::kAccepted && to_breakpoint && state_.t >= t_land - kTimeEpsilon * h) {
      state_.history_steps = 0;
    }
    if (result.status == StepStatus::kAccepted) {
      const StepContext& ctx = integrator_->last_context();
      const OutputSample current = MakeSample(model_, state_, ctx, h, result.newton.iterations);
      // A step that started from projected velocities (after a drive's rate jump) moves from them, not from the rates
      // the last step ended with: its samples start there, with its own forces.
      if (const State* start = integrator_->last_projected_start()) {
        State moved_from = *start;
        moved_from.lambda = state_.lambda;
        previous_ = MakeSample(model_, moved_from, ctx, h, result.newton.iterations);
      }
      if (sample_period == 0) {
        sink(current);
      } else {
        for (double t = t_start_ + next_sample_ * sample_period; t <= current.t + kTimeEpsilon * h;
             t = t_start_ + ++next_sample_ * sample_period) {
          sink(Interpolate(previous_, current, t));
        }
      }
      previous_ = current;
    }
    if (h_next < solver.dt_min) Fail("step size fell below dt_min", h_next, result);
    h_ = h_next;
  }
}

}  // namespace flexmbd
