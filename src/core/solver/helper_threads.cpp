#include "helper_threads.hpp"

#include <chrono>
#include <utility>

namespace flexmbd {
namespace {
// How long a helper waits for the next Wake, yielding its core, before it sleeps. Longer than the gaps between the
// assemblies of a run (a refactorisation of the published antenna takes about 200 us, a step's end and its samples
// less), so that a helper seldom sleeps in a run: waking one costs the caller a system call and, as the scheduler
// tends to put the woken thread on the waker's core, often the caller's core itself (1,500 more involuntary context
// switches of the calling thread in case 0 with a 100 us spin). Yielding instead of spinning hard hands the core to
// any other runnable thread, so that on a loaded machine the waiting helper takes nothing from other jobs
// (bench/README.md, "Helpers that yield while they wait").
constexpr std::chrono::microseconds kSpin{2000};
}  // namespace

HelperThreads::HelperThreads(int count, std::function<void()> task) : task_(std::move(task)) {
  threads_.reserve(count);
  for (int k = 0; k < count; ++k) threads_.emplace_back([this] { Loop(); });
}

HelperThreads::~HelperThreads() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  woken_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void HelperThreads::Wake() {
  // Sequentially consistent, as is the helpers' count of sleepers below: either a helper about to sleep sees the
  // new count, or this sees it asleep and notifies under the lock it waits with.
  wakes_.fetch_add(1);
  if (sleeping_.load() == 0) return;
  { std::lock_guard<std::mutex> lock(mutex_); }
  woken_.notify_all();
}

long HelperThreads::WaitForWake(long seen) {
  const auto spin_end = std::chrono::steady_clock::now() + kSpin;
  while (std::chrono::steady_clock::now() < spin_end) {
    if (wakes_.load() != seen) return wakes_.load();
    if (stopping_.load()) return -1;
    std::this_thread::yield();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  sleeping_.fetch_add(1);
  woken_.wait(lock, [&] { return wakes_.load() != seen || stopping_.load(); });
  sleeping_.fetch_sub(1);
  return stopping_.load() ? -1 : wakes_.load();
}

void HelperThreads::Loop() {
  long seen = 0;
  while ((seen = WaitForWake(seen)) >= 0) task_();
}

}  // namespace flexmbd
