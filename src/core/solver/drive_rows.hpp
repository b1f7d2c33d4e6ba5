#pragma once
// The explicit time dependence of the constraint rows: only a drive's row, q - f(t), has one. Also the rates the
// drives impose either side of an instant, and the instants at which their laws' rates jump (docs/theory.md,
// "Jumps of a drive's rate").

#include <Eigen/Core>

namespace flexmbd {

class Model;
struct State;

/// Per constraint row (multiplier), the derivative of order `order` (1 or 2) of the law f(t) that a drive's row
/// q - f(t) follows, at state.t and one-sided where the law has a kink (the right derivative, as a driven variable's
/// initial rate f'(0)); zero on every other row, and on a drive that follows a commanded set-point instead.
Eigen::VectorXd DriveLawDerivatives(const Model& model, const State& state, int order);

/// Instants closer than this [s] (relative to 1 s or to the time, whichever is larger) are one instant of a drive law:
/// far below any step, far above the round-off of a time reached by a step cut to land on it.
constexpr double kSameInstant = 1.0e-12;

/// Which side of an instant a rate is taken on.
enum class RateSide { kBefore, kAfter };

/// Per joint variable, the rate its drive imposes just before or just after state.t: that of the commanded set-point's
/// lag, (s - q) / tau, or of the drive's law (at a kink of the law, the rate on that side of it); zero on variables
/// without a drive [rad/s or m/s].
Eigen::VectorXd DriveRates(const Model& model, const State& state, RateSide side);

}  // namespace flexmbd
