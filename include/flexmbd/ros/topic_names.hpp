#pragma once
/// @file
/// Names of the topics that carry the samples, the same on the wire and in a bag (docs/ros.md).

#include <string>

namespace flexmbd {
namespace ros {

// Topic names as the node advertises them: joint_states in the node's namespace, /tf, /tf_static and /clock
// global, the others in the node's private namespace.
constexpr char kJointStatesTopic[] = "joint_states";
constexpr char kTfTopic[] = "/tf";
constexpr char kTfStaticTopic[] = "/tf_static";
constexpr char kClockTopic[] = "/clock";
constexpr char kEnergyTopic[] = "energy";
constexpr char kReactionsTopic[] = "reactions";
constexpr char kSolverTopic[] = "solver";
constexpr char kContactsTopic[] = "contacts";
constexpr char kFrictionTopic[] = "friction";
constexpr char kBeamLoadsTopic[] = "beam_loads";
constexpr char kAeroLoadsTopic[] = "aero_loads";
constexpr char kMarkersTopic[] = "markers";
// Command inputs (sensor_msgs/JointState), in the node's private namespace.
constexpr char kEffortCommandTopic[] = "effort_command";
constexpr char kPositionCommandTopic[] = "position_command";

/// Fully resolved topic names.
struct TopicNames {
  std::string joint_states;  ///< sensor_msgs/JointState
  std::string energy;        ///< flexmbd/Energy
  std::string reactions;     ///< flexmbd/JointReactionArray
  std::string solver;        ///< flexmbd/SolverStep
  std::string contacts;      ///< flexmbd/JointContactArray (models with stops)
  std::string friction;      ///< flexmbd/JointFrictionArray (models with frictional joints)
  std::string beam_loads;    ///< flexmbd/BeamLoadsArray (models with beam stations)
  std::string aero_loads;    ///< flexmbd/AeroLoadsArray (models with aero sections or strip stations)
  std::string tf;            ///< tf2_msgs/TFMessage
  std::string tf_static;     ///< tf2_msgs/TFMessage, latched (models with fixed massless links)
  std::string markers;       ///< visualization_msgs/MarkerArray
};

/// The node's name in the launch files; the runner records its bags under this name.
constexpr char kDefaultNodeName[] = "/flexmbd";

/// The names of the node kDefaultNodeName in the root namespace, without remapping: /joint_states,
/// /flexmbd/energy, ... (what the runner writes to its bags).
TopicNames DefaultTopicNames();

}  // namespace ros
}  // namespace flexmbd
