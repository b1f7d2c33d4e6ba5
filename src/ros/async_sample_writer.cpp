#include "flexmbd/ros/async_sample_writer.hpp"

#include <algorithm>
#include <iterator>

namespace flexmbd {
namespace ros {

AsyncSampleWriter::AsyncSampleWriter(SampleFanOut* outputs, size_t wake_batch)
    : outputs_(outputs), wake_batch_(std::max<size_t>(wake_batch, 1)), thread_([this] { WriteLoop(); }) {}

AsyncSampleWriter::~AsyncSampleWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.insert(queue_.end(), std::make_move_iterator(outbox_.begin()), std::make_move_iterator(outbox_.end()));
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

AsyncSampleWriter::RecordPtr AsyncSampleWriter::Acquire() {
  if (spare_.empty()) {
    std::lock_guard<std::mutex> lock(mutex_);
    spare_.swap(recycled_);  // one lock per batch of records, not per record
  }
  if (spare_.empty()) return std::make_unique<SampleRecord>();
  RecordPtr record = std::move(spare_.back());
  spare_.pop_back();
  return record;
}

void AsyncSampleWriter::Submit(RecordPtr record) {
  outbox_.push_back(std::move(record));
  if (outbox_.size() >= wake_batch_) Wake();
}

void AsyncSampleWriter::Flush() {
  Wake();
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return (queue_.empty() && !writing_) || write_error_; });
  RethrowWriteError();
}

void AsyncSampleWriter::Wake() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < kMaxQueued || write_error_; });
  RethrowWriteError();
  queue_.insert(queue_.end(), std::make_move_iterator(outbox_.begin()), std::make_move_iterator(outbox_.end()));
  outbox_.clear();
  // a thread busy writing takes the queue when it is done; one asleep is woken (a system call, costly on a
  // VM), after the lock is released so that it does not wake into a held lock
  const bool wake = !awake_ && !writing_ && !queue_.empty();
  awake_ = awake_ || wake;
  lock.unlock();
  if (wake) changed_.notify_all();
}

void AsyncSampleWriter::RethrowWriteError() {
  if (!write_error_) return;
  std::exception_ptr error = write_error_;
  write_error_ = nullptr;
  queue_.clear();
  outbox_.clear();
  std::rethrow_exception(error);
}

void AsyncSampleWriter::WriteLoop() {
  std::unique_lock<std::mutex> lock(mutex_);
  std::vector<RecordPtr> batch;
  while (true) {
    changed_.wait(lock, [this] { return (awake_ && !queue_.empty()) || stopping_; });
    if (queue_.empty()) return;  // stopping, with everything written
    // take the whole queue: one lock per batch, not per sample, keeps the solver's Submit uncontended
    const bool was_full = queue_.size() >= kMaxQueued;
    batch.swap(queue_);
    awake_ = false;
    writing_ = true;
    const bool write = !failed_;  // after a failed write the run has ended: later samples are dropped
    lock.unlock();
    if (was_full) changed_.notify_all();  // Submit may wait for room
    std::exception_ptr error;
    try {
      if (write) {
        for (const RecordPtr& record : batch) outputs_->Write(record->sample, record->messages);
        outputs_->EndBatch();
      }
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    recycled_.insert(recycled_.end(), std::make_move_iterator(batch.begin()), std::make_move_iterator(batch.end()));
    batch.clear();
    writing_ = false;
    if (error) {
      write_error_ = error;
      failed_ = true;
    }
    awake_ = awake_ || !queue_.empty();  // samples that came meanwhile: the next batch
    changed_.notify_all();               // Flush may wait for this
  }
}

}  // namespace ros
}  // namespace flexmbd
