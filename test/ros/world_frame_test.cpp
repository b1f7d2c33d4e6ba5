// WorldFrameName (include/flexmbd/ros/world_frame.hpp): the parent frame of the link transforms.

#include "flexmbd/ros/world_frame.hpp"

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"

namespace flexmbd {
namespace ros {
namespace {

std::string OneLinkUrdf(const std::string& root, bool root_has_inertia) {
  const std::string inertial =
      "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>";
  return "<robot name=\"r\"><link name=\"" + root + "\">" + (root_has_inertia ? inertial : "") +
         "</link><link name=\"arm\">" + inertial + "</link><joint name=\"hinge\" type=\"continuous\"><parent link=\"" +
         root + "\"/><child link=\"arm\"/><axis xyz=\"0 0 1\"/></joint></robot>";
}

std::string FrameOf(const std::string& urdf) {
  const Model model = BuildModel(LoadModelSpecFromStrings(urdf, "r.urdf", YAML::Node(), ""));
  return WorldFrameName(urdf, model);
}

TEST(WorldFrame, GroundRootLinkNamesTheFrame) { EXPECT_EQ(FrameOf(OneLinkUrdf("base_link", false)), "base_link"); }

TEST(WorldFrame, FreeFloatingRootBodyGivesWorld) { EXPECT_EQ(FrameOf(OneLinkUrdf("base_link", true)), "world"); }

}  // namespace
}  // namespace ros
}  // namespace flexmbd
