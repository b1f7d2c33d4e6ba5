// The steps that land on a time the run must reach (StepToLanding, docs/theory.md (T12), "Last steps"): within the
// window the time left in the fewest equal steps no longer than the proposal (stretched by 1% at most), farther away
// the proposal, and after a rejection the proposal cut to the time left, so that every retry is shorter than the step
// rejected.

#include <gtest/gtest.h>

#include <cmath>

#include "flexmbd/solver/step_to_landing.hpp"

namespace flexmbd {
namespace step_to_landing_test {

constexpr double kProposal = 2.0e-3;  // [s]

TEST(StepToLanding, FarFromTheTimeTakesTheProposal) {
  EXPECT_EQ(StepToLanding(kProposal, kProposal * (1 + kLandingStretch) * kLastSteps * 1.001, kLastSteps, false),
            kProposal);
  EXPECT_EQ(StepToLanding(kProposal, 1.0, kLastSteps, true), kProposal);
}

TEST(StepToLanding, SharesTheTimeLeftInTheFewestEqualStepsThatFit) {
  // 2.1 proposals left: three steps of 0.7 (two would be 5% longer than the proposal).
  EXPECT_DOUBLE_EQ(StepToLanding(kProposal, 2.1 * kProposal, kLastSteps, false), 0.7 * kProposal);
  EXPECT_DOUBLE_EQ(StepToLanding(kProposal, 1.4 * kProposal, kLastSteps, false), 0.7 * kProposal);
  EXPECT_DOUBLE_EQ(StepToLanding(kProposal, 0.7 * kProposal, kLastSteps, false), 0.7 * kProposal);
  // 2.015 proposals left: two steps stretched by 0.75%, not three of 0.67.
  EXPECT_DOUBLE_EQ(StepToLanding(kProposal, 2.015 * kProposal, kLastSteps, false), 1.0075 * kProposal);
  // The window of one of breakpoints and at_times instants: the step cut to it, or stretched by 1% at most.
  EXPECT_DOUBLE_EQ(StepToLanding(kProposal, 1.005 * kProposal, 1, false), 1.005 * kProposal);
  EXPECT_EQ(StepToLanding(kProposal, 1.02 * kProposal, 1, false), kProposal);
  EXPECT_DOUBLE_EQ(StepToLanding(kProposal, 0.1 * kProposal, 1, false), 0.1 * kProposal);
}

TEST(StepToLanding, NeverLongerThanTheStretchNorAtAllAfterARejection) {
  // Times left of every ratio to the proposal up to the window and beyond, on a fine grid.
  for (int k = 1; k <= 10000; ++k) {
    const double left = kProposal * k * (kLastSteps + 1.0) / 10000.0;
    const double step = StepToLanding(kProposal, left, kLastSteps, false);
    const double retry = StepToLanding(kProposal, left, kLastSteps, true);
    EXPECT_LE(step, kProposal * (1 + kLandingStretch)) << left;
    EXPECT_LE(retry, kProposal) << left;
    EXPECT_LE(retry, left) << left;
    // Within the window: equal steps that land on the time, at most kLastSteps of them, each at least
    // (n - 1) / n of the proposal, so that the steps before never fall below half of it.
    const double count = left / step;
    if (count <= kLastSteps + 1e-9) {
      EXPECT_NEAR(count, std::round(count), 1e-9) << left;
      if (count > 1.5) {
        EXPECT_GE(step, kProposal * (std::round(count) - 1) / std::round(count)) << left;
      }
    } else {
      EXPECT_EQ(step, kProposal) << left;
    }
  }
  // A retry within round-off of the time left, after a rejection there, is not stretched back to it.
  const double left = 1.0e-3, retry = left * (1 - 1e-12);
  EXPECT_LT(StepToLanding(retry, left, kLastSteps, true), left);
}

}  // namespace step_to_landing_test
}  // namespace flexmbd
