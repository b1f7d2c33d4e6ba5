#pragma once
// The sample messages of one run, as received on topics or read from a bag.

#include <vector>

#include "flexmbd/ros/message_conversions.hpp"

namespace flexmbd {
namespace test {

/// Messages in arrival (or bag) order.
struct Samples {
  std::vector<sensor_msgs::JointState> joint_states;
  std::vector<Energy> energy;
  std::vector<JointReactionArray> reactions;
  std::vector<SolverStep> solver;
  std::vector<tf2_msgs::TFMessage> transforms;
  std::vector<JointContactArray> contacts;  ///< only for models with stops
  std::vector<JointFrictionArray> friction;  ///< only for models with friction
  std::vector<BeamLoadsArray> beam_loads;    ///< only for models with beam stations
  std::vector<AeroLoadsArray> aero_loads;    ///< only for models with aero sections or strip stations
};

/// Simulated time of a message [s].
template <typename Message>
double TimeOf(const Message& message) {
  return message.header.stamp.toSec();
}

}  // namespace test
}  // namespace flexmbd
