#include "flexmbd/ros/clock_ticks.hpp"

namespace flexmbd {
namespace ros {

ClockTicks::ClockTicks(double rate_hz) : rate_hz_(rate_hz) {}

void ClockTicks::Restart(double t0) {
  queued_.clear();
  t0_ = t0;
  next_ = 1;
  last_ = t0;
  queued_.push_back(t0);
}

void ClockTicks::Reached(double t) {
  if (rate_hz_ > 0.0) {
    // ticks on the grid t0 + k / rate, counted rather than summed so that they do not drift
    for (double tick = t0_ + next_ / rate_hz_; tick <= t; tick = t0_ + ++next_ / rate_hz_) queued_.push_back(tick);
    return;
  }
  if (t - last_ < 1.0 / kMaxClockRateHz) return;
  last_ = t;
  queued_.push_back(t);
}

}  // namespace ros
}  // namespace flexmbd
