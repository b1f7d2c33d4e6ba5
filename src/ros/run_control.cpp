#include "flexmbd/ros/run_control.hpp"

namespace flexmbd {
namespace ros {
namespace {
const char kClosed[] = "the run has ended; the node is shutting down";
}  // namespace

RunControl::Reply RunControl::Request(Command command) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (closed_) return Reply{false, kClosed};
  posted_ = command;
  reply_.reset();
  loop_wakeup_.notify_all();
  reply_ready_.wait(lock, [this] { return reply_.has_value() || closed_; });
  if (!reply_) return Reply{false, kClosed};
  Reply reply = std::move(*reply_);
  reply_.reset();
  return reply;
}

std::optional<RunControl::Command> RunControl::Take() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<Command> command = posted_;
  posted_.reset();
  return command;
}

void RunControl::Answer(Reply reply) {
  std::lock_guard<std::mutex> lock(mutex_);
  reply_ = std::move(reply);
  reply_ready_.notify_all();
}

void RunControl::WaitUntil(Clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(mutex_);
  loop_wakeup_.wait_until(lock, deadline, [this] { return posted_.has_value() || notified_; });
  notified_ = false;
}

void RunControl::Notify() {
  std::lock_guard<std::mutex> lock(mutex_);
  notified_ = true;
  loop_wakeup_.notify_all();
}

void RunControl::Close() {
  std::lock_guard<std::mutex> lock(mutex_);
  closed_ = true;
  posted_.reset();
  reply_ready_.notify_all();
}

}  // namespace ros
}  // namespace flexmbd
