// UrdfFrameTree (include/flexmbd/ros/transform_frames.hpp): the tf tree shaped like the URDF, on small URDFs
// written here, placed by the initial state.

// first: it includes the flexmbd messages before namespace flexmbd::ros exists (the generated headers name
// ros::message_operations from inside namespace flexmbd)
#include "flexmbd/ros/message_conversions.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "flexmbd/io/config_loader.hpp"

namespace flexmbd {
namespace ros {
namespace transform_frames_test {

// Poses are a few products of rotations and lengths of order 1 m: round-off is a few ulp of 1.
constexpr double kRoundOff = 1.0e-12;

const std::string kInertial =
    "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>";

std::string Link(const std::string& name, bool massive) {
  return "<link name=\"" + name + "\">" + (massive ? kInertial : "") + "</link>";
}

std::string Joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child, const std::string& origin) {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent + "\"/><child link=\"" +
         child + "\"/><origin " + origin + "/><axis xyz=\"0 0 1\"/></joint>";
}

// tool0 fixed on link arm, 0.5 m along its x axis and turned 90 deg about z.
std::string Tool0Flange() {
  return Link("tool0", false) +
         Joint("flange", "fixed", "arm", "tool0", "xyz=\"0.5 0 0\" rpy=\"0 0 1.5707963267948966\"");
}

struct Case {
  Model model;
  FrameTree tree;
};

Case Load(const std::string& body) {
  const std::string urdf = "<robot name=\"r\">" + body + "</robot>";
  Model model = BuildModel(LoadModelSpecFromStrings(urdf, "r.urdf", YAML::Node(), ""));
  FrameTree tree = UrdfFrameTree(urdf, model);
  return Case{std::move(model), std::move(tree)};
}

void ExpectFrame(const StaticFrame& frame, const std::string& name, const std::string& parent, const Mat3& R_PF,
                 const Vec3& p_PF) {
  EXPECT_EQ(frame.name, name);
  EXPECT_EQ(frame.parent, parent);
  EXPECT_NEAR((frame.R_PF - R_PF).norm(), 0.0, kRoundOff) << name;
  EXPECT_NEAR((frame.p_PF - p_PF).norm(), 0.0, kRoundOff) << name;
}

TEST(TransformFrames, GroundRootLinkIsTheWorldFrame) {
  const Case arm = Load(Link("base_link", false) + Link("arm", true) +
                        Joint("hinge", "continuous", "base_link", "arm", "xyz=\"0 0 0\""));
  EXPECT_EQ(arm.tree.world_frame, "base_link");
  ASSERT_EQ(arm.tree.moving.size(), 1u);
  EXPECT_EQ(arm.tree.moving[0].parent, "base_link");
  EXPECT_TRUE(arm.tree.fixed.empty());
}

TEST(TransformFrames, FreeFloatingRootBodyIsAChildOfWorld) {
  const Case arm = Load(Link("base_link", true) + Link("arm", true) +
                        Joint("hinge", "continuous", "base_link", "arm", "xyz=\"0 0 0\""));
  EXPECT_EQ(arm.tree.world_frame, "world");
  ASSERT_EQ(arm.tree.moving.size(), 2u);
  EXPECT_EQ(arm.tree.moving[0].name, "base_link");
  EXPECT_EQ(arm.tree.moving[0].parent, "world");
  EXPECT_EQ(arm.tree.moving[1].parent, "base_link");
}

TEST(TransformFrames, MasslessFixedLinksAreStaticFramesOnTheirParent) {
  // Reference: the joint origins. base_link is fixed 2 m above world; tool0 is fixed on the moving arm, 0.5 m
  // along its x axis and turned 90 deg about z.
  const Case arm = Load(Link("world", false) + Link("base_link", false) + Link("arm", true) +
                        Joint("mount", "fixed", "world", "base_link", "xyz=\"0 0 2\"") +
                        Joint("hinge", "continuous", "base_link", "arm", "xyz=\"0 0 0\"") +
                        Tool0Flange());
  ASSERT_EQ(arm.tree.fixed.size(), 2u);
  ExpectFrame(arm.tree.fixed[0], "base_link", "world", Mat3::Identity(), Vec3(0, 0, 2));
  ExpectFrame(arm.tree.fixed[1], "tool0", "arm", Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()).toRotationMatrix(),
              Vec3(0.5, 0, 0));
  const tf2_msgs::TFMessage msg = ToStaticTransforms(arm.tree.fixed);
  ASSERT_EQ(msg.transforms.size(), 2u);
  EXPECT_EQ(msg.transforms[1].header.frame_id, "arm");
  EXPECT_EQ(msg.transforms[1].child_frame_id, "tool0");
  EXPECT_NEAR(msg.transforms[1].transform.rotation.z, std::sin(M_PI / 4), kRoundOff);
}

TEST(TransformFrames, BodyBelowAFrameOnAMovingBodyIsPlacedFromThatFrame) {
  // Reference: the finger's joint origin, (0.1, 0, 0) in tool0 at zero joint angle; tool0 sits on the arm at
  // (0.5, 0, 0) turned 90 deg about z, so a wrong composition of the two would move the finger off it.
  const Case arm = Load(Link("world", false) + Link("arm", true) + Link("finger", true) +
                        Joint("hinge", "continuous", "world", "arm", "xyz=\"0 0 1\"") +
                        Tool0Flange() +
                        Joint("knuckle", "continuous", "tool0", "finger", "xyz=\"0.1 0 0\""));
  ASSERT_EQ(arm.tree.moving.size(), 2u);
  EXPECT_EQ(arm.tree.moving[1].parent, "tool0");
  tf2_msgs::TFMessage msg;
  FillTransforms(arm.tree.moving, arm.model.initial_state(), &msg);
  const geometry_msgs::TransformStamped& finger = msg.transforms[1];
  EXPECT_EQ(finger.header.frame_id, "tool0");
  EXPECT_NEAR(finger.transform.translation.x, 0.1, kRoundOff);
  EXPECT_NEAR(finger.transform.translation.y, 0.0, kRoundOff);
  EXPECT_NEAR(finger.transform.translation.z, 0.0, kRoundOff);
  EXPECT_NEAR(std::abs(finger.transform.rotation.w), 1.0, kRoundOff);
}

}  // namespace transform_frames_test
}  // namespace ros
}  // namespace flexmbd
