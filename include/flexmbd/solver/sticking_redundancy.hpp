#pragma once
/// @file
/// Sticking rows of frictional joints that repeat the other constraint rows (docs/theory.md (F7)): a slider held
/// through a closed loop by a drive on the crank, or a slider at its crank's dead centre. Such a row makes the
/// iteration matrix singular; it is left out of the step, and the constraints it repeats hold the joint.

#include <vector>

#include <Eigen/Core>

#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {

class Model;
struct State;
struct EffectState;

class StickingRedundancy {
 public:
  explicit StickingRedundancy(const Model& model);

  /// Sets EffectState::held_by_constraints in `modes` for every frictional joint: true for one sticking in
  /// `modes` whose sticking row lies in the span of the other constraint rows active in them at the positions of
  /// `state` (joints, closures, drives, stops in contact, and the sticking rows of joints kept before it in the
  /// model's order), false otherwise. A joint that stayed stuck with its row in over the step that led to
  /// `state` (a steady stick) keeps its row untested.
  void Mark(const State& state, std::vector<EffectState>* modes);

 private:
  // The active constraint rows at `state` in `modes`, each as its nonzero (kinematic column, value) pairs.
  void CollectRows(const State& state, const std::vector<EffectState>* modes);
  // True when row `row` lies in the span of the rows marked in `kept` that share columns with it, directly or
  // through other such rows.
  bool Repeats(int row, const std::vector<bool>& kept) const;

  const Model& model_;
  StepContextBuilder builder_;
  std::vector<const Element*> constrained_;  ///< the elements with constraint rows
  std::vector<NodeSchemeCoefficients> trapezoidal_;
  std::vector<std::vector<std::pair<int, double>>> rows_;  ///< by multiplier: (kinematic column, value)
  std::vector<std::vector<int>> column_rows_;              ///< by kinematic column: the rows with an entry there
};

}  // namespace flexmbd
