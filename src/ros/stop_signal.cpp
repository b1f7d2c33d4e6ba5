#include "flexmbd/ros/stop_signal.hpp"

#include <atomic>
#include <csignal>

namespace flexmbd {
namespace ros {
namespace {

std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");

void OnStopSignal(int) { stop_requested = true; }

}  // namespace

void InstallStopHandlers() {
  std::signal(SIGINT, OnStopSignal);
  std::signal(SIGTERM, OnStopSignal);
}

bool StopRequested() { return stop_requested; }

}  // namespace ros
}  // namespace flexmbd
