// TangentReuse: a model whose reused factorisations hold keeps reusing them; one whose factorisations fail
// (a stiff beam that turns) stops after a few failures, retries now and then, and resumes once retries hold.

#include <gtest/gtest.h>

#include "flexmbd/solver/tangent_reuse.hpp"

namespace flexmbd {
namespace tangent_reuse_test {

// Runs `steps` eligible steps whose attempts all hold or all fail; returns how many attempted.
int Attempts(TangentReuse* reuse, int steps, bool held) {
  int count = 0;
  for (int k = 0; k < steps; ++k) {
    if (!reuse->Attempt()) continue;
    ++count;
    reuse->Record(held);
  }
  return count;
}

TEST(TangentReuse, ReusesWhileTheFactorisationsHold) {
  TangentReuse chain;
  EXPECT_EQ(Attempts(&chain, 1000, true), 1000);
}

TEST(TangentReuse, StopsAfterFailuresAndRetriesOneStepInSixteen) {
  constexpr int kSteps = 1600;
  TangentReuse beam;
  const int attempts = Attempts(&beam, kSteps, false);
  // A share of held attempts starting at 1 and weighted 0.2 falls below 0.5 after 4 failures; then one eligible
  // step in 16 retries: 4 + about 100.
  EXPECT_GE(attempts, 4 + kSteps / 16 - 1);
  EXPECT_LE(attempts, 4 + kSteps / 16);
}

TEST(TangentReuse, ResumesWhenRetriesHoldAgain) {
  TangentReuse reuse;
  Attempts(&reuse, 100, false);
  // Ten attempts failed (4, then a retry every 16 steps): the share is 0.8^10 = 0.11. Retries that hold lift it
  // to 0.29, 0.43 and 0.54: from the third retry (48 steps) on, every step attempts again.
  EXPECT_GE(Attempts(&reuse, 200, true), 200 - 48);
}

}  // namespace tangent_reuse_test
}  // namespace flexmbd
