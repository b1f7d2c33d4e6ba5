// ClockTicks (include/flexmbd/ros/clock_ticks.hpp): the times the node sends on /clock.

#include "flexmbd/ros/clock_ticks.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace flexmbd {
namespace ros {
namespace clock_ticks_test {

std::vector<double> Drain(ClockTicks* ticks) {
  std::vector<double> times;
  for (; !ticks->empty(); ticks->pop()) times.push_back(ticks->front());
  return times;
}

TEST(ClockTicks, GridTicksUpToEachTimeReached) {
  // Reference: the grid t0 + k / rate, k counted (100 Hz from t0 = 0: k / 100, exactly as divided).
  ClockTicks ticks(100.0);
  ticks.Restart(0.0);
  ticks.Reached(0.035);
  EXPECT_EQ(Drain(&ticks), (std::vector<double>{0.0, 0.01, 0.02, 0.03}));
  ticks.Reached(0.05);
  EXPECT_EQ(Drain(&ticks), (std::vector<double>{4 / 100.0, 5 / 100.0}));
}

TEST(ClockTicks, EveryStepTicksAtMostAtTheBoundRate) {
  // Reference: kMaxClockRateHz = 1000: a time reached less than 1 ms after the last tick gives none.
  ClockTicks ticks(0.0);
  ticks.Restart(0.0);
  for (const double t : {0.0005, 0.002, 0.0025, 0.01}) ticks.Reached(t);
  EXPECT_EQ(Drain(&ticks), (std::vector<double>{0.0, 0.002, 0.01}));
}

TEST(ClockTicks, RestartStartsOverAtTheNewTime) {
  ClockTicks ticks(10.0);
  ticks.Restart(0.0);
  ticks.Reached(0.25);
  ticks.Restart(1.0);
  ticks.Reached(1.1);
  EXPECT_EQ(Drain(&ticks), (std::vector<double>{1.0, 1.0 + 1 / 10.0}));
}

}  // namespace clock_ticks_test
}  // namespace ros
}  // namespace flexmbd
