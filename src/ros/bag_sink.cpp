#include "flexmbd/ros/bag_sink.hpp"

#include <rosbag/exceptions.h>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace ros {

std::optional<BagCompression> ParseBagCompression(const std::string& text) {
  if (text == "none") return BagCompression::kNone;
  if (text == "lz4") return BagCompression::kLz4;
  return std::nullopt;
}

::ros::Time BagTime(const ::ros::Time& stamp) { return std::max(stamp, ::ros::TIME_MIN); }

BagSink::BagSink(const std::string& path, BagCompression compression, const TopicNames& topics,
                 const visualization_msgs::MarkerArray& markers)
    : topics_(topics) {
  try {
    bag_.open(path, rosbag::bagmode::Write);
  } catch (const rosbag::BagException& error) {
    throw ConfigError("cannot open bag '" + path + "' for writing (" + error.what() +
                      "); expected a writable file path");
  }
  bag_.setCompression(compression == BagCompression::kLz4 ? rosbag::compression::LZ4
                                                          : rosbag::compression::Uncompressed);
  bag_.write(topics_.markers, ::ros::TIME_MIN, markers);
}

BagSink::~BagSink() { Close(); }

void BagSink::Write(const SampleMessages& messages) {
  const ::ros::Time time = BagTime(messages.joint_state.header.stamp);
  bag_.write(topics_.joint_states, time, messages.joint_state);
  bag_.write(topics_.energy, time, messages.energy);
  bag_.write(topics_.reactions, time, messages.reactions);
  bag_.write(topics_.solver, time, messages.solver);
  if (!messages.contacts.contacts.empty()) bag_.write(topics_.contacts, time, messages.contacts);
  if (!messages.friction.joints.empty()) bag_.write(topics_.friction, time, messages.friction);
  if (!messages.beam_loads.stations.empty()) bag_.write(topics_.beam_loads, time, messages.beam_loads);
  if (messages.has_transforms && !messages.transforms.transforms.empty()) {
    bag_.write(topics_.tf, BagTime(messages.transforms.transforms.front().header.stamp), messages.transforms);
  }
}

void BagSink::Close() {
  if (bag_.isOpen()) bag_.close();
}

}  // namespace ros
}  // namespace flexmbd
