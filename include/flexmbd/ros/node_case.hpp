#pragma once
/// @file
/// What the node runs: its settings and the model from the parameter server, loaded by the same loader as
/// the runner's files.

#include <ros/node_handle.h>

#include <string>

#include "flexmbd/model/model.hpp"
#include "flexmbd/ros/node_settings.hpp"
#include "flexmbd/ros/sample_fan_out.hpp"
#include "flexmbd/ros/transform_frames.hpp"

namespace flexmbd {
namespace ros {

struct NodeCase {
  NodeSettings settings;
  Model model;              ///< output.rate_hz replaced by ~rate_hz when given
  FrameTree frames;         ///< the tf tree of the URDF
  RecordingFiles files;     ///< ~bag (or output.bag) and output.csv
};

/// Loads the URDF from ~urdf_file or else the robot_description parameter (searched up the namespaces), and
/// the extension parameters from everything under the private namespace except the node's settings,
/// converted to YAML for LoadModelSpecFromStrings. Throws ConfigError with the loader's one-line message
/// (naming the file or parameter and the expected form), or naming the missing URDF source.
NodeCase LoadNodeCase(const ::ros::NodeHandle& node, const ::ros::NodeHandle& private_node);

}  // namespace ros
}  // namespace flexmbd
