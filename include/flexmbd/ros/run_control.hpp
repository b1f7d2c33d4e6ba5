#pragma once
/// @file
/// Passes the commands of the node's services (~pause, ~resume, ~step, ~reset) to the run loop. A service
/// call returns once the loop has acted on its command, so a client that sees the reply knows the state.

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>

namespace flexmbd {
namespace ros {

class RunControl {
 public:
  using Clock = std::chrono::steady_clock;
  enum class Command { kPause, kResume, kStep, kReset };
  struct Reply {
    bool success = false;
    std::string message;
  };

  /// Service side: posts `command` and waits for the loop's reply. One command at a time (the services are
  /// served by one spinner thread). After Close(), replies at once with success = false.
  Reply Request(Command command);

  /// Loop side: the command posted and not yet taken, if any.
  std::optional<Command> Take();

  /// Loop side: replies to the command taken last.
  void Answer(Reply reply);

  /// Loop side: waits until a command is posted, Notify() is called or `deadline` passes.
  void WaitUntil(Clock::time_point deadline);

  /// Wakes the loop from WaitUntil (e.g. a subscriber has connected).
  void Notify();

  /// Loop side: no more commands will be taken; a waiting request and every later one fail.
  void Close();

 private:
  std::mutex mutex_;
  std::condition_variable loop_wakeup_, reply_ready_;
  std::optional<Command> posted_;
  std::optional<Reply> reply_;
  bool notified_ = false;
  bool closed_ = false;
};

}  // namespace ros
}  // namespace flexmbd
