#pragma once
/// @file
/// The node's own parameters (docs/ros.md), read once from its private namespace. Everything else under that
/// namespace is the model's extension parameters.

#include <ros/node_handle.h>

#include <optional>
#include <string>
#include <vector>

#include "flexmbd/ros/bag_sink.hpp"

namespace flexmbd {
namespace ros {

struct NodeSettings {
  std::string urdf_file;           ///< ~urdf_file: URDF path; empty: the robot_description parameter
  double real_time_factor = 0.0;   ///< ~real_time_factor: simulated seconds per wall second; 0 = no pacing
  std::optional<std::string> bag;  ///< ~bag: bag path, overrides output.bag; "" = none
  BagCompression bag_compression = BagCompression::kNone;  ///< ~bag_compression: none | lz4
  bool publish = true;                                     ///< ~publish: publish samples on topics
  std::optional<double> rate_hz;  ///< ~rate_hz: overrides output.rate_hz [Hz]; 0 = every accepted step
  bool keep_alive = false;        ///< ~keep_alive: stay up (services answer) when the run ends
  int wait_for_subscribers = 0;   ///< ~wait_for_subscribers: start once every sample topic has this many
  double wait_for_subscribers_timeout = 60.0;  ///< ~wait_for_subscribers_timeout: give up waiting after this [s]
  bool paused = false;            ///< ~paused: start paused (~step, ~resume go on)
  double clock_rate_hz = 0.0;     ///< ~clock_rate_hz: /clock ticks per simulated second; 0 = every step
  double setpoint_time_constant = 0.1;  ///< ~setpoint_time_constant: lag of a drive behind its set-point [s]
};

/// The private parameter the node writes (not a setting): the topics it publishes for its model
/// (TopicPublisher::RecordedTopics), for the launch files' recorder (scripts/record_node_topics.py).
constexpr char kRecordedTopicsParam[] = "recorded_topics";

/// Names of the settings above, relative to the private namespace.
const std::vector<std::string>& NodeSettingNames();

/// Reads the settings from `private_node` (the node's "~" handle), with the defaults above for those not set.
/// Throws ConfigError naming the parameter, its value and the expected form when one has the wrong type or
/// range.
NodeSettings ReadNodeSettings(const ::ros::NodeHandle& private_node);

}  // namespace ros
}  // namespace flexmbd
