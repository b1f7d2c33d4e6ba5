#pragma once
/// @file
/// Records every sample to a bag through the rosbag C++ API (no master needed). Layout (docs/ros.md): the
/// sample topics of TopicNames, each message recorded at its header stamp (~contacts, ~friction and
/// ~beam_loads only for a model that has stops, frictional joints or beam stations), plus the markers once at
/// the start.

#include <rosbag/bag.h>

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
  /// Creates (or truncates) the bag at `path` and records `markers`. Throws ConfigError naming the path if
  /// it cannot be opened.
  BagSink(const std::string& path, BagCompression compression, const TopicNames& topics,
          const visualization_msgs::MarkerArray& markers);
  ~BagSink() override;

  void Write(const SampleMessages& messages) override;

  /// Writes the index and closes the file, so `rosbag info` reads it; also done by the destructor.
  void Close() override;

 private:
  rosbag::Bag bag_;
  TopicNames topics_;
};

}  // namespace ros
}  // namespace flexmbd
