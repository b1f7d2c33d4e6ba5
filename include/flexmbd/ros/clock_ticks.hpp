#pragma once
/// @file
/// The simulated times the node sends on /clock (docs/ros.md): on a grid of a rate the user sets, or at
/// every accepted step and every sample, never more often than kMaxClockRateHz of simulated time. A
/// rospy.Rate or ros::Rate loop under use_sim_time then runs at its own rate, not at the sample rate.

#include <deque>

namespace flexmbd {
namespace ros {

/// Most clock ticks per simulated second: with steps of a microsecond a tick per step would send millions.
constexpr double kMaxClockRateHz = 1000.0;

class ClockTicks {
 public:
  /// @param rate_hz ticks per simulated second, in (0, kMaxClockRateHz]; 0: at each time Reached (step ends and
  /// samples), at least 1 / kMaxClockRateHz apart.
  explicit ClockTicks(double rate_hz);

  /// Starts over at `t0` [s] (a new run): its first tick.
  void Restart(double t0);

  /// The simulation has reached time `t` [s] (a step end or a sample, in increasing order): queues the ticks
  /// up to it.
  void Reached(double t);

  bool empty() const { return queued_.empty(); }
  /// The earliest tick not yet sent [s]. @pre !empty()
  double front() const { return queued_.front(); }
  void pop() { queued_.pop_front(); }

 private:
  double rate_hz_;
  double t0_ = 0.0;    ///< start of the run [s]
  long next_ = 0;      ///< index of the next grid tick (rate_hz_ > 0)
  double last_ = 0.0;  ///< time of the last tick queued (rate_hz_ = 0) [s]
  std::deque<double> queued_;
};

}  // namespace ros
}  // namespace flexmbd
