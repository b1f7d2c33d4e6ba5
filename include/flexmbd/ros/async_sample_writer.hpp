#pragma once
/// @file
/// Writes samples to a SampleFanOut from a thread of its own, so that serialising, sending and recording them never
/// hold up the solver. Samples are written in the order they are submitted, none is dropped (until a write fails, which
/// ends the run): when the writer falls kMaxQueued samples behind, Submit waits for it. Waking the thread costs a
/// context switch (several microseconds, as much as a small model's step), and so does taking its lock under
/// contention: submitted samples are handed over `wake_batch` at a time, under one lock, and the thread woken for them;
/// Wake() and Flush() hand over what was submitted since. Records travel between the threads by pointer and are
/// recycled: once written, a record goes back to the run loop (Acquire), whose next sample reuses its vectors and
/// strings, so a sample costs no allocation on either thread after the first few.

#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "flexmbd/ros/sample_fan_out.hpp"

namespace flexmbd {
namespace ros {

/// A sample and its messages, on their way from the run loop to the sinks.
struct SampleRecord {
  OutputSample sample;
  SampleMessages messages;
};

class AsyncSampleWriter {
 public:
  using RecordPtr = std::unique_ptr<SampleRecord>;

  /// Samples the writer may lag behind the solver before Submit waits: bounds the memory of a burst.
  static constexpr size_t kMaxQueued = 10000;

  /// @param outputs must outlive the writer; it is only touched by the writer's thread until Flush returns.
  /// @param wake_batch samples submitted before they are handed to the thread and it is woken (1: at once).
  AsyncSampleWriter(SampleFanOut* outputs, size_t wake_batch);
  /// Writes what is queued, then stops the thread.
  ~AsyncSampleWriter();

  /// Run-loop side: a record to fill, one the writer has written (its storage kept) or else a new one.
  RecordPtr Acquire();

  /// Run-loop side: queues `record` for writing. Waits while the writer is kMaxQueued samples behind.
  void Submit(RecordPtr record);

  /// Hands the samples submitted over to the thread (waiting while it is kMaxQueued behind) and wakes it
  /// (call before waiting: they are then written meanwhile).
  void Wake();

  /// Waits until every submitted sample is written (each batch the thread takes ends with
  /// SampleFanOut::EndBatch); afterwards the caller may use the fan-out directly
  /// until the next Submit. Rethrows an exception the fan-out raised while writing (as Submit and Wake do),
  /// once: the writer drops every sample after a failed write, and a later Flush waits for it to be idle.
  void Flush();

 private:
  void WriteLoop();
  void RethrowWriteError();

  SampleFanOut* outputs_;
  size_t wake_batch_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<RecordPtr> queue_;     ///< submitted, not yet taken by the thread
  std::vector<RecordPtr> recycled_;  ///< written, for Acquire
  std::vector<RecordPtr> spare_;     ///< run loop's own stock of recycled records (taken without the lock)
  std::vector<RecordPtr> outbox_;    ///< submitted, not yet handed over (run loop only, without the lock)
  bool writing_ = false;  ///< the thread holds records it took off the queue
  bool awake_ = false;    ///< the thread writes until the queue is empty
  bool stopping_ = false;
  bool failed_ = false;              ///< a write failed: later samples are dropped
  std::exception_ptr write_error_;  ///< the failure, until it is rethrown to the run loop
  std::thread thread_;  ///< last: starts once the members above exist
};

}  // namespace ros
}  // namespace flexmbd
