// launch/double_pendulum.launch: the node starts from the launch file's parameters and publishes the sample
// topics, the link frames and the latched body markers.

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "flexmbd/ros/message_conversions.hpp"

namespace flexmbd {
namespace test {
namespace double_pendulum_launch_test {

// Bound on roslaunch start-up on a loaded 2-core machine; met in about a second.
const ::ros::Duration kTimeout(30.0);

TEST(DoublePendulumLaunch, PublishesJointStatesNamedAfterTheUrdf) {
  const auto message = ::ros::topic::waitForMessage<sensor_msgs::JointState>("/joint_states", kTimeout);
  ASSERT_TRUE(message);
  EXPECT_EQ(message->name, (std::vector<std::string>{"shoulder", "elbow"}));
}

TEST(DoublePendulumLaunch, PublishesTheEnergy) {
  const auto message = ::ros::topic::waitForMessage<Energy>("/flexmbd/energy", kTimeout);
  ASSERT_TRUE(message);
  EXPECT_GE(message->kinetic, 0.0);
}

TEST(DoublePendulumLaunch, ReactionsNameTheWorldFrame) {
  // Reference: msg/JointReactionArray.msg: forces in the world frame, the URDF's ground root link "world".
  const auto message = ::ros::topic::waitForMessage<JointReactionArray>("/flexmbd/reactions", kTimeout);
  ASSERT_TRUE(message);
  EXPECT_EQ(message->header.frame_id, "world");
}

TEST(DoublePendulumLaunch, PublishesTheLinkFramesInTheUrdfRoot) {
  const auto message = ::ros::topic::waitForMessage<tf2_msgs::TFMessage>("/tf", kTimeout);
  ASSERT_TRUE(message);
  ASSERT_EQ(message->transforms.size(), 2u);
  EXPECT_EQ(message->transforms[0].header.frame_id, "world");
  EXPECT_EQ(message->transforms[0].child_frame_id, "link1");
  EXPECT_EQ(message->transforms[1].child_frame_id, "link2");
}

TEST(DoublePendulumLaunch, LatchesTheBodyMarkers) {
  const auto message = ::ros::topic::waitForMessage<visualization_msgs::MarkerArray>("/flexmbd/markers", kTimeout);
  ASSERT_TRUE(message);
  EXPECT_EQ(message->markers.size(), 4u);  // per body: a sphere and its sticks
}

}  // namespace double_pendulum_launch_test
}  // namespace test
}  // namespace flexmbd
