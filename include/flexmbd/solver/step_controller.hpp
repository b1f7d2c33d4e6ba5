#pragma once
/// @file
/// Step-size policy, separate from the integrator: shrinks after a rejection, follows the local error
/// estimate otherwise, and keeps the books (steps accepted, rejected and why).

#include <map>
#include <string>

#include "flexmbd/model/model_spec.hpp"
#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {

struct StepStatistics {
  long accepted = 0;
  long rejected_error = 0;
  long rejected_event = 0;     ///< redone to resolve a stop or friction event
  long rejected_newton = 0;
  long rejected_singular = 0;
  long newton_iterations = 0;  ///< over all attempted steps
  long tangents = 0;           ///< Newton iterations that assembled and factorised a fresh tangent
  long trial = 0;              ///< steps from the start that chose the first step size (docs/theory.md, (T12))
  double h_start = 0;          ///< the first step size they chose [s]
  double h_min = 0, h_max = 0; ///< smallest and largest accepted step [s]
  /// Per unknown (the first of a node's translation or rotation, or a joint variable): how many times its local
  /// error weighed most in a step the estimate shrank or rejected.
  std::map<int, long> limited_by;
  long rejected() const { return rejected_error + rejected_event + rejected_newton + rejected_singular; }
  /// One line: "steps: N accepted, M rejected (a error, b event, c Newton, d singular); i Newton iterations (t
  /// with a fresh tangent); ...; k trial steps chose the first step h s; local error limited the step most at
  /// <unknown> (k times)".
  std::string Summary(const Model& model) const;
};

class StepController {
 public:
  /// After a Newton failure or a singular matrix the step is cut by this factor.
  static constexpr double kFailureShrink = 0.25;
  /// The change of step size an error estimate asks for, before the bounds on one change.
  static double SizeFactor(double error);
  /// SizeFactor within the bounds on one change of step size.
  static double BoundedSizeFactor(double error);

  explicit StepController(const SolverSpec& solver);

  /// Books a trial step from the start (ChooseStartingStep), which the run does not keep.
  void BookTrial(const StepResult& result);
  /// The run starts with steps of size h: without an estimate the first steps stay at it.
  void Start(double h);
  /// A motion of a new pace starts (a commanded set-point): until the estimate restarts, the steps stay at most h.
  void Restart(double h);

  /// Books the outcome of a step of size h and returns the size of the next attempt [s].
  double Next(double h, const StepResult& result);

  const StepStatistics& statistics() const { return stats_; }

 private:
  SolverSpec solver_;
  StepStatistics stats_;
  double previous_error_ = 0;   ///< estimate of the last accepted step (0: none since the start or a jump)
  bool rejected_last_ = false;  ///< the step after a rejection does not grow (Hairer & Wanner, sec. II.4)
  double estimated_next_;  ///< the step the last error estimate allowed (at first, the first step) [s]
};

}  // namespace flexmbd
