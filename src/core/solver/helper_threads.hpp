#pragma once
// Threads kept for the life of their owner that run one fixed task each time they are woken (the parallel
// element evaluation, parallel_assembly.hpp). A woken helper that finds nothing left to do returns at once; after
// a task it waits for the next, yielding its core, for a few milliseconds before it sleeps, since a Newton
// iteration's next assembly follows within tens to hundreds of microseconds, and waking a sleeping thread costs
// about as much and may take the caller's core.

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace flexmbd {

class HelperThreads {
 public:
  /// Starts `count` threads, each running `task` once per Wake() (possibly once for several Wakes that came
  /// while it was busy). The task must tolerate being run when there is no work.
  HelperThreads(int count, std::function<void()> task);
  ~HelperThreads();
  HelperThreads(const HelperThreads&) = delete;
  HelperThreads& operator=(const HelperThreads&) = delete;

  /// Has every helper run the task again; returns at once. Allocates nothing.
  void Wake();

 private:
  void Loop();
  /// Waits for a Wake after `seen`; returns the wake count then, or -1 when the helpers are to stop.
  long WaitForWake(long seen);

  std::function<void()> task_;
  std::atomic<long> wakes_{0};
  std::atomic<int> sleeping_{0};
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::condition_variable woken_;
  std::vector<std::thread> threads_;
};

}  // namespace flexmbd
