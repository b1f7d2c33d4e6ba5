#include "helper_threads.hpp"

#include <chrono>
#include <utility>

namespace flexmbd {
namespace {
// How long a helper spins for the next Wake before it sleeps. A simplified Newton iteration (a KLU solve and a
// residual) takes 50-100 us on the published antenna, a refactorisation about 200 us: this catches the residual
// assemblies of the simplified iterations without holding a core through a factorisation
// (bench/README.md, "Element evaluation on two threads, a persistent pool").
constexpr std::chrono::microseconds kSpin{100};
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
