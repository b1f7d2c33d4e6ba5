#include "flexmbd/ros/async_sample_writer.hpp"

#include <algorithm>

namespace flexmbd {
namespace ros {

AsyncSampleWriter::AsyncSampleWriter(SampleFanOut* outputs, size_t wake_batch)
    : outputs_(outputs), wake_batch_(std::max<size_t>(wake_batch, 1)), thread_([this] { WriteLoop(); }) {}

AsyncSampleWriter::~AsyncSampleWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void AsyncSampleWriter::Submit(OutputSample sample, SampleMessages messages) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < kMaxQueued || write_error_; });
  RethrowWriteError();
  queue_.push_back(Item{std::move(sample), std::move(messages)});
  if (!awake_ && queue_.size() >= wake_batch_) {
    awake_ = true;
    changed_.notify_all();
  }
}

void AsyncSampleWriter::Wake() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!awake_ && !queue_.empty()) {
    awake_ = true;
    changed_.notify_all();
  }
}

void AsyncSampleWriter::Flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!queue_.empty()) {
    awake_ = true;
    changed_.notify_all();
  }
  changed_.wait(lock, [this] { return (queue_.empty() && !writing_) || write_error_; });
  RethrowWriteError();
}

void AsyncSampleWriter::RethrowWriteError() {
  if (!write_error_) return;
  std::exception_ptr error = write_error_;
  write_error_ = nullptr;
  queue_.clear();
  std::rethrow_exception(error);
}

void AsyncSampleWriter::WriteLoop() {
  std::unique_lock<std::mutex> lock(mutex_);
  std::deque<Item> batch;
  while (true) {
    changed_.wait(lock, [this] { return (awake_ && !queue_.empty()) || stopping_; });
    if (queue_.empty()) return;  // stopping, with everything written
    // take the whole queue: one lock per batch, not per sample, keeps the solver's Submit uncontended
    const bool was_full = queue_.size() >= kMaxQueued;
    batch.swap(queue_);
    awake_ = false;
    writing_ = true;
    lock.unlock();
    if (was_full) changed_.notify_all();  // Submit may wait for room
    std::exception_ptr error;
    try {
      for (const Item& item : batch) outputs_->Write(item.sample, item.messages);
    } catch (...) {
      error = std::current_exception();
    }
    batch.clear();
    lock.lock();
    writing_ = false;
    if (error) write_error_ = error;
    awake_ = awake_ || !queue_.empty();  // samples that came meanwhile: the next batch
    changed_.notify_all();               // Flush may wait for this
  }
}

}  // namespace ros
}  // namespace flexmbd
