#pragma once
/// @file
/// When an energy-decaying step judges which dissipation terms it keeps (docs/theory.md, "Newton iteration"):
/// early, on an iterate converged to a loose tolerance, or only at full convergence. Early judging saves a
/// second full solve where dropping terms moves the solution far (stiff beams) and costs a third, partial one
/// where it does not (rigid chains), so the choice is made per model from the Newton iterations its steps take
/// under each: both are tried in turn, then the cheaper one is used, with the other tried again now and then.
/// Deterministic: it depends on the iteration counts only, never on timings.

namespace flexmbd {

class DissipationJudging {
 public:
  /// Whether the next step judges early.
  bool Early() const;
  /// Books the Newton iterations of a step judged as `early` said.
  void Record(bool early, int iterations);

 private:
  // Steps taken under each choice before comparing, and the share of steps that keep trying the other one.
  static constexpr int kTrialSteps = 8;
  static constexpr int kRetryEvery = 16;
  // Weight of one step in the running means (about the last 1 / kWeight steps of each choice count).
  static constexpr double kWeight = 0.1;

  long steps_ = 0;
  long samples_[2] = {0, 0};  ///< by choice: [late, early]
  double mean_[2] = {0, 0};   ///< running mean of the iterations per step, by choice
};

}  // namespace flexmbd
