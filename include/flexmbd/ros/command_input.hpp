#pragma once
/// @file
/// The node's command topics (docs/ros.md, "Commands"): ~effort_command and ~position_command, both
/// sensor_msgs/JointState naming joint variables. The spinner thread resolves each message's names and keeps
/// the latest value per variable; the run loop applies what arrived to the simulation before its next step.
/// A bad entry is skipped with a warning that names it (each distinct warning is logged once).

#include <ros/node_handle.h>
#include <sensor_msgs/JointState.h>

#include <map>
#include <mutex>
#include <set>
#include <string>
#include <utility>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace ros {

class CommandInput {
 public:
  enum class Kind { kEffort, kPosition };

  /// Subscribes to the command topics of `private_node`. Set-points lead drives with `setpoint_time_constant`
  /// [s]. `model` must outlive this object.
  CommandInput(::ros::NodeHandle private_node, const Model& model, double setpoint_time_constant);

  /// Spinner side: resolves `message`'s names and keeps its values of `kind` (effort[] or position[]).
  void Receive(Kind kind, const sensor_msgs::JointState& message);

  /// Run loop side: applies the commands received since the last call to `simulation` (from its next step).
  void ApplyTo(Simulation* simulation);

  /// Run loop side: forgets the commands not yet applied (a reset starts without commands).
  void Discard();

 private:
  void WarnOnce(const std::string& text);

  const Model& model_;
  double setpoint_time_constant_;
  ::ros::Subscriber effort_subscriber_, position_subscriber_;
  std::mutex mutex_;  ///< guards received_
  std::map<std::pair<Kind, int>, double> received_;  ///< latest value per kind and variable, not yet applied
  std::mutex warned_mutex_;  ///< guards warned_ (both threads warn)
  std::set<std::string> warned_;
};

}  // namespace ros
}  // namespace flexmbd
