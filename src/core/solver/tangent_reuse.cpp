#include "flexmbd/solver/tangent_reuse.hpp"

namespace flexmbd {

bool TangentReuse::Attempt() {
  if (held_share_ >= kMinHeld || ++skipped_ >= kRetryEvery) {
    skipped_ = 0;
    return true;
  }
  return false;
}

void TangentReuse::Record(bool held) { held_share_ += kWeight * ((held ? 1.0 : 0.0) - held_share_); }

}  // namespace flexmbd
