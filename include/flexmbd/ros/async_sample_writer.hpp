#pragma once
/// @file
/// Writes samples to a SampleFanOut from a thread of its own, so that serialising, sending and recording
/// them never hold up the solver. Samples are written in the order they are submitted, none is dropped: when
/// the writer falls kMaxQueued samples behind, Submit waits for it. Waking the thread costs a context switch
/// (several microseconds, as much as a small model's step): it is woken once `wake_batch` samples wait, or
/// by Wake() and Flush().

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "flexmbd/ros/sample_fan_out.hpp"

namespace flexmbd {
namespace ros {

class AsyncSampleWriter {
 public:
  /// Samples the writer may lag behind the solver before Submit waits: bounds the memory of a burst.
  static constexpr size_t kMaxQueued = 10000;

  /// @param outputs must outlive the writer; it is only touched by the writer's thread until Flush returns.
  /// @param wake_batch samples queued before the thread is woken (1: at once).
  AsyncSampleWriter(SampleFanOut* outputs, size_t wake_batch);
  /// Writes what is queued, then stops the thread.
  ~AsyncSampleWriter();

  void Submit(OutputSample sample, SampleMessages messages);

  /// Wakes the thread for the samples queued (call before waiting: they are then written meanwhile).
  void Wake();

  /// Waits until every submitted sample is written; afterwards the caller may use the fan-out directly
  /// until the next Submit. Rethrows an exception the fan-out raised while writing.
  void Flush();

 private:
  struct Item {
    OutputSample sample;
    SampleMessages messages;
  };
  void WriteLoop();
  void RethrowWriteError();

  SampleFanOut* outputs_;
  size_t wake_batch_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Item> queue_;
  bool writing_ = false;  ///< the thread holds an item it took off the queue
  bool awake_ = false;    ///< the thread writes until the queue is empty
  bool stopping_ = false;
  std::exception_ptr write_error_;
  std::thread thread_;  ///< last: starts once the members above exist
};

}  // namespace ros
}  // namespace flexmbd
