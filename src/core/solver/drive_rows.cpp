// The explicit time dependence of the constraint rows: the drives' laws, and the rates they impose.

#include "drive_rows.hpp"

#include <algorithm>
#include <cmath>

#include "flexmbd/common/error.hpp"
#include "flexmbd/effects/variable_effects.hpp"
#include "flexmbd/math/time_function.hpp"
#include "flexmbd/model/model.hpp"

namespace flexmbd {

Eigen::VectorXd DriveLawDerivatives(const Model& model, const State& state, int order) {
  FLEXMBD_DEMAND(order == 1 || order == 2);
  Eigen::VectorXd derivatives = Eigen::VectorXd::Zero(model.num_multipliers());
  for (const auto& element : model.elements()) {
    const auto* drive = dynamic_cast<const VariableDrive*>(element.get());
    if (drive == nullptr || state.commands[drive->variable()].has_setpoint) continue;
    // a drive's unknowns are its variable's and its multiplier's
    const int row = drive->unknowns()[1] - model.num_kinematic();
    derivatives[row] = order == 1 ? EvaluateRate(drive->law(), state.t) : EvaluateSecondRate(drive->law(), state.t);
  }
  return derivatives;
}

namespace {
double SameInstantTolerance(double t) { return kSameInstant * std::max(1.0, std::abs(t)); }
}  // namespace

Eigen::VectorXd DriveRates(const Model& model, const State& state, RateSide side) {
  Eigen::VectorXd rates = Eigen::VectorXd::Zero(model.num_variables());
  for (const auto& element : model.elements()) {
    const auto* drive = dynamic_cast<const VariableDrive*>(element.get());
    if (drive == nullptr) continue;
    const int k = drive->variable();
    const VariableCommand& command = state.commands[k];
    if (command.has_setpoint) {
      rates[k] = (command.setpoint - state.q[k]) / command.time_constant;
    } else if (const std::optional<RateJump> jump =
                   RateJumpNear(drive->law(), state.t, SameInstantTolerance(state.t))) {
      rates[k] = side == RateSide::kBefore ? jump->before : jump->after;
    } else {
      rates[k] = EvaluateRate(drive->law(), state.t);
    }
  }
  return rates;
}

}  // namespace flexmbd
