#include "flexmbd/effects/modal_effect.hpp"

#include <algorithm>

namespace flexmbd {

void StepLimit::Merge(const StepLimit& other) {
  retry = std::min(retry, other.retry);
  next = std::min(next, other.next);
}

}  // namespace flexmbd
