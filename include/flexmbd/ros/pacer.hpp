#pragma once
/// @file
/// Wall-clock pacing of the published samples by a real-time factor.

#include <chrono>

namespace flexmbd {
namespace ros {

class Pacer {
 public:
  using Clock = std::chrono::steady_clock;

  /// @param real_time_factor simulated seconds per wall second; 0 paces nothing (every sample is due at once).
  explicit Pacer(double real_time_factor);

  /// Anchors the pace: the sample at simulated time `t` [s] is due at `now`.
  void Anchor(double t, Clock::time_point now);

  /// When the sample at simulated time `t` [s] is due.
  Clock::time_point Due(double t) const;

 private:
  double real_time_factor_;
  double anchor_t_ = 0.0;
  Clock::time_point anchor_wall_;
};

}  // namespace ros
}  // namespace flexmbd
