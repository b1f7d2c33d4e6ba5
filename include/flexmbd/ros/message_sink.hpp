#pragma once
/// @file
/// Where the messages of a sample go: topics or a bag.

#include "flexmbd/ros/sample_converter.hpp"

namespace flexmbd {
namespace ros {

class MessageSink {
 public:
  virtual ~MessageSink() = default;
  virtual void Write(const SampleMessages& messages) = 0;
  /// Ends a batch of Writes: a sink that holds messages back to pass them on together passes them on here.
  virtual void EndBatch() {}
  /// Flushes and releases what the sink holds; Write is not called afterwards.
  virtual void Close() {}
};

}  // namespace ros
}  // namespace flexmbd
