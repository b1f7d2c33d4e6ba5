#pragma once
/// @file
/// Runs an analysis on a Model: static equilibrium, time stepping with the step controller, output samples
/// at the configured rate (interpolated inside accepted steps, so the output rate never limits the step).

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/effect_events.hpp"
#include "flexmbd/solver/time_integrator.hpp"
#include "flexmbd/solver/output_sample.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/static_solver.hpp"
#include "flexmbd/solver/step_controller.hpp"

namespace flexmbd {

class Simulation {
 public:
  using SampleSink = std::function<void(const OutputSample&)>;
  using StateSink = std::function<void(const State&)>;

  explicit Simulation(const Model& model);

  /// Runs what the model's solver settings ask for (static, or dynamic with an optional static start),
  /// passing every output sample to `sink`. Throws SolverError when the run cannot go on.
  void Run(const SampleSink& sink);

  /// As Run, and a dynamic run also lands a step on each of `instants` (increasing, in [0, t_end] [s]) and
  /// passes the state there to `at_instant` before it goes on (solver.eigen.at_times).
  void Run(const SampleSink& sink, const std::vector<double>& instants, const StateSink& at_instant);

  /// Static equilibrium from the current state. Throws SolverError if Newton fails.
  StaticResult SolveStaticEquilibrium();

  /// The start of a dynamic run with solver.static_first: the static equilibrium, with the rates of a static start
  /// (docs/theory.md (K4): every drive at its rate, the rest at rest relative to what carries it). Throws
  /// SolverError if Newton fails.
  void SolveStaticStart();

  /// Time stepping from the current state to t_end: Begin, then AdvanceTo(t_end, t_end).
  void Integrate(double t_end, const SampleSink& sink);

  /// Starts time stepping at the current state (after any static analysis) and emits its sample.
  void Begin(const SampleSink& sink);

  /// Takes steps until the state reaches t_until, emitting every sample due on the way. Steps are not cut to
  /// land on t_until (the output never limits the step), only on t_end and on the time functions' breakpoints before
  /// it (Model::breakpoints), after which the error estimate restarts. Call after Begin;
  /// calls may follow one another (pause and resume between them). Throws SolverError when it cannot go on.
  void AdvanceTo(double t_until, double t_end, const SampleSink& sink);

  /// Once `stop()` returns true, AdvanceTo (and so Run) returns at the end of the step in progress, with that
  /// step's samples emitted, and Run passes no further instant to its `at_instant` (the runner's SIGINT and
  /// SIGTERM). `stop` is polled between steps; none by default.
  void StopWhen(std::function<bool()> stop) { stop_ = std::move(stop); }

  /// Commands (docs/theory.md, "Commands"), in force from the next step on until changed; their work is
  /// external work. SetEffort applies `effort` [N m or N] on joint variable `variable`. SetSetpoint makes a driven
  /// variable follow `setpoint` [rad or m] with a first-order lag of `time_constant` [s] instead of its law. Both
  /// throw ConfigError naming the variable for a value that is not finite, a variable out of range, a time
  /// constant not > 0 or a set-point for a variable without a drive.
  void SetEffort(int variable, double effort);
  void SetSetpoint(int variable, double setpoint, double time_constant);

  /// Attempts one step of size h; on acceptance the state advances. Books the outcome.
  StepResult TryStep(double h);

  const State& state() const { return state_; }
  const Model& model() const { return model_; }
  const StepStatistics& statistics() const { return controller_.statistics(); }
  const SparseSystem& system() const { return system_; }
  /// The context of the last Newton iteration of the last step attempted (valid until the next step): what
  /// benchmarks and tests evaluate a model at.
  const StepContext& last_context() const { return integrator_->last_context(); }
  /// Every mode change of the effects with modes so far, in time order.
  const std::vector<EffectEvent>& effect_events() const { return effect_events_; }

 private:
  OutputSample SampleAtState(double dt, int iterations);
  [[noreturn]] void Fail(const char* what, double h, const StepResult& last) const;
  void CheckCommand(int variable, const char* what, double value) const;

  const Model& model_;
  State state_;
  SparseSystem system_;
  std::unique_ptr<TimeIntegrator> integrator_;
  StepController controller_;
  std::vector<EffectEvent> effect_events_;
  // Time-stepping progress between AdvanceTo calls.
  OutputSample previous_;   ///< sample at the last accepted step, the left end of interpolation
  long next_sample_ = 1;    ///< index of the next sample time t_start_ + k / rate
  double t_start_ = 0.0;    ///< time of the first sample [s]
  double h_ = 0.0;          ///< size of the next step attempt [s]
  std::function<bool()> stop_;  ///< StopWhen

  bool Stopped() const { return stop_ && stop_(); }
};

}  // namespace flexmbd
