#pragma once
/// @file
/// Whether a dynamic step starts from the factorisation of the step before (docs/theory.md, "Newton
/// iteration"). A reused factorisation saves an assembly and a factorisation when it still contracts, and costs
/// two wasted iterations when it does not (its first increment is taken back). Which happens is a property of the
/// model: a pendulum chain's tangent changes little from step to step, while a stiff beam that turns by a
/// fraction of a degree has its axial stiffness, 1e5 times its bending stiffness and inertia, pointing elsewhere,
/// and the old tangent diverges. The choice is learnt per model from the outcome of its attempts: reuse while
/// most recent attempts held, otherwise attempt only every kRetryEvery-th step, so a change of regime is
/// followed. Deterministic: it depends on the outcomes only, never on timings.

namespace flexmbd {

class TangentReuse {
 public:
  /// Whether the next step whose size allows it should start from the previous factorisation.
  bool Attempt();
  /// Books the outcome of an attempt: whether the solve converged on the reused factorisation, without a fresh
  /// tangent.
  void Record(bool held);

 private:
  // Weight of one attempt in the running share of attempts that held (about the last 1 / kWeight count).
  static constexpr double kWeight = 0.2;
  // Attempt while at least this share held; otherwise once in kRetryEvery eligible steps.
  static constexpr double kMinHeld = 0.5;
  static constexpr int kRetryEvery = 16;

  double held_share_ = 1.0;  ///< running share of attempts that held; optimistic until measured
  long skipped_ = 0;         ///< eligible steps that did not attempt since the last attempt
};

}  // namespace flexmbd
