// main of the rostest gtest nodes: gtest, then ROS (the tests subscribe and call services).

#include <gtest/gtest.h>
#include <ros/ros.h>

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "flexmbd_integration_test");
  ros::NodeHandle keep_ros_up;
  return RUN_ALL_TESTS();
}
