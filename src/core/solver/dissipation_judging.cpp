#include "flexmbd/solver/dissipation_judging.hpp"

namespace flexmbd {

bool DissipationJudging::Early() const {
  // Alternate until each choice has its trial steps.
  if (samples_[0] < kTrialSteps || samples_[1] < kTrialSteps) return steps_ % 2 == 1;
  const bool early_is_cheaper = mean_[1] < mean_[0];
  const bool retry = steps_ % kRetryEvery == 0;
  return early_is_cheaper != retry;
}

void DissipationJudging::Record(bool early, int iterations) {
  const int k = early ? 1 : 0;
  mean_[k] = samples_[k] == 0 ? iterations : mean_[k] + kWeight * (iterations - mean_[k]);
  ++samples_[k];
  ++steps_;
}

}  // namespace flexmbd
