#pragma once
/// @file
/// Conversions from the core's output (OutputSample, State, Model) to ROS messages. Pure functions: no
/// master, no publishing. The per-sample ones fill a message in place: a message filled again for a later
/// sample of the same model keeps its arrays and strings, so converting allocates nothing after the first
/// sample (the node recycles its messages). They leave the header alone: SampleConverter stamps and numbers
/// the messages of a sample, once for all.

#include <ros/time.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

#include "flexmbd/AeroLoadsArray.h"
#include "flexmbd/BeamLoadsArray.h"
#include "flexmbd/Energy.h"
#include "flexmbd/JointContactArray.h"
#include "flexmbd/JointFrictionArray.h"
#include "flexmbd/JointReactionArray.h"
#include "flexmbd/SolverStep.h"
#include "flexmbd/model/model.hpp"
#include "flexmbd/ros/transform_frames.hpp"
#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {
namespace ros {

/// Simulated time t >= 0 [s] as a stamp, rounded to the nanosecond.
::ros::Time ToStamp(double t);

/// Position, velocity and effort of every joint variable; names are Model::variable_names(), in order.
void FillJointState(const Model& model, const OutputSample& sample, sensor_msgs::JointState* msg);

void FillEnergy(const OutputSample& sample, Energy* msg);

/// One entry per joint: its reaction, named and ordered as Model::joints().
void FillJointReactions(const Model& model, const OutputSample& sample, JointReactionArray* msg);

void FillSolverStep(const OutputSample& sample, SolverStep* msg);

/// One entry per stop: sample.stops[k] named by stops[k] (Model::stops(): the same order and size).
void FillJointContacts(const std::vector<StopInfo>& stops, const OutputSample& sample, JointContactArray* msg);

/// One entry per frictional joint: sample.friction[k] named by frictions[k] (Model::frictions(): the same
/// order and size).
void FillJointFriction(const std::vector<FrictionInfo>& frictions, const OutputSample& sample,
                       JointFrictionArray* msg);

/// One entry per beam station: sample.beam_stations[k] named by stations[k] (Model::beam_stations(): the same
/// order and size).
void FillBeamLoads(const std::vector<BeamStationInfo>& stations, const OutputSample& sample, BeamLoadsArray* msg);

/// One entry per aero section (sample.aero_sections[k] named by Model::aero_sections()[k]) and one per strip
/// station (sample.strip_stations[k] named by Model::strip_stations()[k]).
void FillAeroLoads(const Model& model, const OutputSample& sample, AeroLoadsArray* msg);

/// One transform per frame of `frames` (FrameTree::moving) from its parent frame to it, both placed by their
/// nodes in `state`, stamped with the state's time.
void FillTransforms(const std::vector<TransformFrame>& frames, const State& state, tf2_msgs::TFMessage* msg);

/// One transform per fixed frame (FrameTree::fixed) from its parent link, stamped 0: for /tf_static, where
/// a transform holds at every time.
tf2_msgs::TFMessage ToStaticTransforms(const std::vector<StaticFrame>& frames);

/// Markers for rviz, each locked to a tf frame (so they follow /tf and are published once): per body a
/// sphere at the centre of mass and lines from it to the body's joints, in its link frame; per beam node a
/// sphere at the node, in its node frame (BeamNodeFrameName), so the string of spheres traces the deformed
/// centre line.
visualization_msgs::MarkerArray ToBodyMarkers(const Model& model);

}  // namespace ros
}  // namespace flexmbd
