#pragma once
// The explicit time dependence of the constraint rows: only a drive's row, q - f(t), has one.

#include <Eigen/Core>

namespace flexmbd {

class Model;
struct State;

/// Per constraint row (multiplier), the derivative of order `order` (1 or 2) of the law f(t) that a drive's row
/// q - f(t) follows, at state.t and one-sided where the law has a kink (the right derivative, as a driven variable's
/// initial rate f'(0)); zero on every other row, and on a drive that follows a commanded set-point instead.
Eigen::VectorXd DriveLawDerivatives(const Model& model, const State& state, int order);

}  // namespace flexmbd
