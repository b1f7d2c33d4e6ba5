// The explicit time dependence of the constraint rows: the drives' laws.

#include "drive_rows.hpp"

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

}  // namespace flexmbd
