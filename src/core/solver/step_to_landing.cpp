#include "flexmbd/solver/step_to_landing.hpp"

#include <algorithm>
#include <cmath>

namespace flexmbd {

double StepToLanding(double proposal, double left, int window, bool after_rejection) {
  if (after_rejection) return std::min(proposal, left);
  const double steps = std::max(1.0, std::ceil(left / ((1 + kLandingStretch) * proposal)));
  return steps > window ? proposal : left / steps;
}

}  // namespace flexmbd
