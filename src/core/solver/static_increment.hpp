#pragma once
/// @file
/// How a static Newton increment is applied (docs/theory.md, "Static increments"): a joint turns by at most
/// kLargestTurn in one iteration, and an increment that long goes downhill; an open stop the increment would pass
/// stops it (an elastic one just past it, a rigid one on it, which then holds); a joint pressed on an elastic stop
/// goes to the approach at which the law carries the force the increment predicts.

#include <vector>

#include <Eigen/Core>

namespace flexmbd {

class Model;
struct State;

/// The joint variables that are angles [rad] (the turns of revolute, cylindrical, screw, planar and universal joints).
std::vector<int> AngularVariables(const Model& model);

class StaticIncrement {
 public:
  explicit StaticIncrement(const Model& model);

  /// Applies the Newton increment computed from `residual` at *state (J increment = -residual) and returns the
  /// largest motion it applied to a kinematic unknown [m or rad]. `released[k]` marks the rigid stops (Model::stops()
  /// order) a landing must not close: opened again because they pulled.
  double Apply(const Eigen::VectorXd& residual, Eigen::VectorXd increment, const std::vector<bool>& released,
               State* state) const;

 private:
  // The increment with its joint turns bounded, turned downhill when it was that long.
  void BoundTurns(const Eigen::VectorXd& residual, Eigen::VectorXd* increment) const;

  const Model& model_;
  std::vector<int> angular_;  ///< joint variables that are angles
  double round_off_;          ///< of the model's coordinates [m or rad]
};

}  // namespace flexmbd
