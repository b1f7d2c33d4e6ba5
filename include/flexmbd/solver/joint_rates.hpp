#pragma once
/// @file
/// Joint variable rates consistent with the node velocities of a state.

#include <Eigen/Core>

#include "flexmbd/model/state.hpp"

namespace flexmbd {

class Model;

/// For each joint, the rates qdot whose relative twist (RelativeVelocity) best fits, in least squares, the
/// relative twist of the child joint frame in the parent joint frame computed from the node velocities.
Eigen::VectorXd JointRates(const Model& model, const State& state);

}  // namespace flexmbd
