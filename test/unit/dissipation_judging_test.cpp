// DissipationJudging: both choices are tried, the one whose steps take fewer Newton iterations is kept, and the
// other is still tried now and then, so a model whose costs change is followed.

#include <gtest/gtest.h>

#include "flexmbd/solver/dissipation_judging.hpp"

namespace flexmbd {
namespace dissipation_judging_test {

// Runs `steps` steps that cost `late` or `early` iterations; returns how many judged early.
int EarlySteps(DissipationJudging* judging, int steps, int late, int early) {
  int count = 0;
  for (int k = 0; k < steps; ++k) {
    const bool choice = judging->Early();
    count += choice ? 1 : 0;
    judging->Record(choice, choice ? early : late);
  }
  return count;
}

TEST(DissipationJudging, KeepsTheCheaperChoiceAndRetriesTheOther) {
  constexpr int kSteps = 1600;
  // After the 16 trial steps, one step in 16 retries the other choice: about 100 of 1600.
  constexpr int kRetries = kSteps / 16;
  DissipationJudging beam;
  const int early_on_beam = EarlySteps(&beam, kSteps, 8, 5);
  EXPECT_GE(early_on_beam, kSteps - kRetries - 16);
  EXPECT_LT(early_on_beam, kSteps);
  DissipationJudging chain;
  const int early_on_chain = EarlySteps(&chain, kSteps, 5, 8);
  EXPECT_LE(early_on_chain, kRetries + 16);
  EXPECT_GT(early_on_chain, 8);
}

TEST(DissipationJudging, FollowsAModelWhoseCostsChange) {
  DissipationJudging judging;
  EXPECT_GT(EarlySteps(&judging, 400, 8, 5), 350);
  // Early judging becomes the dearer: its running mean rises within a few steps and the retries of the late
  // choice see the lower cost, so the choice turns within a few retries (of 16 steps each).
  EXPECT_LT(EarlySteps(&judging, 400, 5, 8), 100);
}

}  // namespace dissipation_judging_test
}  // namespace flexmbd
