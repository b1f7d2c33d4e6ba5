#pragma once
/// @file
/// Records every sample to a bag through the rosbag C++ API (no master needed). Layout (docs/ros.md): the
/// sample topics of TopicNames, each message recorded at its header stamp (~contacts, ~friction, ~beam_loads
/// and ~aero_loads only for a model that has stops, frictional joints, beam stations, or aero sections or strip
/// stations), plus the markers and the static transforms (if any) once at the start.
///
/// Every write is checked: a failed one (disk full, file size limit) throws OutputError. The bag cannot be
/// closed then (closing writes its index, which fails as well), so it is left unindexed: `rosbag reindex`
/// recovers the samples in its complete chunks (768 KiB each).

#include <rosbag/bag.h>

#include <memory>
#include <optional>
#include <string>

#include "flexmbd/ros/message_sink.hpp"
#include "flexmbd/ros/topic_names.hpp"

namespace flexmbd {
namespace ros {

enum class BagCompression { kNone, kLz4 };

/// "none" or "lz4"; nullopt for anything else.
std::optional<BagCompression> ParseBagCompression(const std::string& text);

/// Time a message is recorded at in a bag: its stamp, raised to the earliest time a bag accepts
/// (ros::TIME_MIN, 1 ns) so that the first sample, at t = 0, can be recorded.
::ros::Time BagTime(const ::ros::Time& stamp);

class BagSink : public MessageSink {
 public:
  /// Creates (or truncates) the bag at `path` and records `markers`, and `static_transforms` unless empty,
  /// as latched (so that `rosbag play` latches them). Throws ConfigError naming the path if it cannot be
  /// opened, OutputError if it cannot be written.
  BagSink(const std::string& path, BagCompression compression, const TopicNames& topics,
          const visualization_msgs::MarkerArray& markers, const tf2_msgs::TFMessage& static_transforms);
  /// Closes the bag as Close() does; a failure then goes unreported (call Close() to learn of it).
  ~BagSink() override;

  /// Records the messages of one sample. Throws OutputError naming the file, the reason and the samples
  /// recorded if writing fails; the sink records nothing afterwards.
  void Write(const SampleMessages& messages) override;

  /// Writes the index and closes the file, so `rosbag info` reads it. Throws OutputError if that fails.
  void Close() override;

 private:
  void WriteSample(const SampleMessages& messages);
  /// Runs `operation` on the bag; gives the bag up (Abandon) if it fails.
  template <typename Operation>
  void Checked(const char* action, Operation operation);
  /// Gives the bag up after `action` failed with `error` (and errno `system_error`, 0 if none): throws
  /// OutputError.
  [[noreturn]] void Abandon(const std::string& action, const std::exception& error, int system_error);

  std::string path_;
  std::unique_ptr<rosbag::Bag> bag_;  ///< null once closed or abandoned
  TopicNames topics_;
  long samples_ = 0;  ///< samples recorded
};

}  // namespace ros
}  // namespace flexmbd
