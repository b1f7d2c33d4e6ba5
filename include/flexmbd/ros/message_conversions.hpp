#pragma once
/// @file
/// Conversions from the core's output (OutputSample, State, Model) to ROS messages. Pure functions: no
/// master, no publishing.

#include <ros/time.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "flexmbd/Energy.h"
#include "flexmbd/JointReactions.h"
#include "flexmbd/SolverStep.h"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {
namespace ros {

/// Simulated time t >= 0 [s] as a stamp, rounded to the nanosecond.
::ros::Time ToStamp(double t);

/// Position, velocity and effort of every joint variable; names are Model::variable_names(), in order.
sensor_msgs::JointState ToJointState(const Model& model, const OutputSample& sample);

Energy ToEnergy(const OutputSample& sample);

/// Reactions of every joint, named and ordered as Model::joints().
JointReactions ToJointReactions(const Model& model, const OutputSample& sample);

SolverStep ToSolverStep(const OutputSample& sample);

/// One transform per body: its link frame (at node x + R p_NBo_N, orientation R) in `world_frame`,
/// stamped with the state's time.
tf2_msgs::TFMessage ToLinkTransforms(const Model& model, const State& state, const std::string& world_frame);

/// Stick-figure markers for rviz, in each body's link frame and locked to it (so they follow /tf and are
/// published once): a sphere at the centre of mass and lines from it to the body's joints.
visualization_msgs::MarkerArray ToBodyMarkers(const Model& model);

}  // namespace ros
}  // namespace flexmbd
