// Pacer (include/flexmbd/ros/pacer.hpp): when each sample is due on the wall clock.

#include "flexmbd/ros/pacer.hpp"

#include <gtest/gtest.h>

namespace flexmbd {
namespace ros {
namespace pacer_test {

using std::chrono::milliseconds;

// Due times are converted to the clock's integer ticks (nanoseconds): allow one tick of rounding.
constexpr auto kTick = std::chrono::nanoseconds(1);

TEST(Pacer, FactorOneFollowsTheWallClockFromTheAnchor) {
  Pacer pacer(1.0);
  const Pacer::Clock::time_point anchor = Pacer::Clock::now();
  pacer.Anchor(2.0, anchor);
  EXPECT_LE(pacer.Due(2.5) - (anchor + milliseconds(500)), kTick);
  EXPECT_GE(pacer.Due(2.5) - (anchor + milliseconds(500)), -kTick);
}

TEST(Pacer, FactorTwoRunsTwiceAsFast) {
  Pacer pacer(2.0);
  const Pacer::Clock::time_point anchor = Pacer::Clock::now();
  pacer.Anchor(0.0, anchor);
  EXPECT_LE(pacer.Due(1.0) - (anchor + milliseconds(500)), kTick);
  EXPECT_GE(pacer.Due(1.0) - (anchor + milliseconds(500)), -kTick);
}

TEST(Pacer, FactorZeroMakesEverySampleDueAtTheAnchor) {
  Pacer pacer(0.0);
  const Pacer::Clock::time_point anchor = Pacer::Clock::now();
  pacer.Anchor(0.0, anchor);
  EXPECT_EQ(pacer.Due(100.0), anchor);
}

}  // namespace pacer_test
}  // namespace ros
}  // namespace flexmbd
