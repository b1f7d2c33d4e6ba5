#include "flexmbd/ros/pacer.hpp"

namespace flexmbd {
namespace ros {

Pacer::Pacer(double real_time_factor) : real_time_factor_(real_time_factor) {}

void Pacer::Anchor(double t, Clock::time_point now) {
  anchor_t_ = t;
  anchor_wall_ = now;
}

Pacer::Clock::time_point Pacer::Due(double t) const {
  if (real_time_factor_ <= 0.0) return anchor_wall_;
  const std::chrono::duration<double> wall_delay((t - anchor_t_) / real_time_factor_);
  return anchor_wall_ + std::chrono::duration_cast<Clock::duration>(wall_delay);
}

}  // namespace ros
}  // namespace flexmbd
