// Conversions from the core's output to ROS messages (include/flexmbd/ros/message_conversions.hpp), on the
// double pendulum reference case.

#include "flexmbd/ros/message_conversions.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace {

// Poses are a few products of rotations and lengths of order 1 m: round-off is a few ulp of 1.
constexpr double kRoundOff = 1.0e-12;
// ros::Time keeps nanoseconds.
constexpr double kStampResolution = 1.0e-9;

OutputSample SampleWithDistinctValues(const Model& model) {
  OutputSample sample;
  sample.t = 1.25;
  const int n = model.num_variables();
  sample.position = Eigen::VectorXd::LinSpaced(n, 0.1, 0.2);
  sample.velocity = Eigen::VectorXd::LinSpaced(n, 1.1, 1.2);
  sample.effort = Eigen::VectorXd::LinSpaced(n, 2.1, 2.2);
  for (size_t k = 0; k < model.joints().size(); ++k) {
    sample.reaction_force_W.push_back(Vec3(1.0, 2.0, 3.0) * (k + 1.0));
    sample.reaction_moment.push_back(Vec3(4.0, 5.0, 6.0) * (k + 1.0));
  }
  sample.kinetic = 1.5;
  sample.potential = 2.5;
  sample.external_work = 3.5;
  sample.dissipated = 4.5;
  sample.numerical_dissipation = 5.5;
  sample.dt = 0.003;
  sample.iterations = 4;
  return sample;
}

TEST(MessageConversions, JointStateNamesTheVariablesInModelOrder) {
  // Reference: the URDF's joints in tree order (shoulder, then elbow), one variable each.
  const Model model = test::DoublePendulum();
  const OutputSample sample = SampleWithDistinctValues(model);
  const sensor_msgs::JointState msg = ToJointState(model, sample);
  EXPECT_EQ(msg.name, (std::vector<std::string>{"shoulder", "elbow"}));
  EXPECT_EQ(msg.position, (std::vector<double>{0.1, 0.2}));
  EXPECT_EQ(msg.velocity, (std::vector<double>{1.1, 1.2}));
  EXPECT_EQ(msg.effort, (std::vector<double>{2.1, 2.2}));
  EXPECT_NEAR(msg.header.stamp.toSec(), 1.25, kStampResolution);
}

TEST(MessageConversions, EnergyCopiesEveryTerm) {
  const Model model = test::DoublePendulum();
  const Energy msg = ToEnergy(SampleWithDistinctValues(model));
  EXPECT_EQ(msg.kinetic, 1.5);
  EXPECT_EQ(msg.potential, 2.5);
  EXPECT_EQ(msg.external_work, 3.5);
  EXPECT_EQ(msg.dissipated, 4.5);
  EXPECT_EQ(msg.numerical_dissipation, 5.5);
}

TEST(MessageConversions, ReactionsAndSolverStepCopyTheSample) {
  const Model model = test::DoublePendulum();
  const OutputSample sample = SampleWithDistinctValues(model);
  const JointReactions reactions = ToJointReactions(model, sample);
  ASSERT_EQ(reactions.name, (std::vector<std::string>{"shoulder", "elbow"}));
  EXPECT_EQ(reactions.force[1].z, 6.0);
  EXPECT_EQ(reactions.moment[1].x, 8.0);
  const SolverStep step = ToSolverStep(sample);
  EXPECT_EQ(step.dt, 0.003);
  EXPECT_EQ(step.iterations, 4);
}

TEST(MessageConversions, LinkTransformsPlaceTheLinkFramesAtTheirJoints) {
  // Reference: link1's frame is at the shoulder (0, 0, 2) with the shoulder at 0 deg (identity); link2's
  // frame is at the elbow, 1 m along link1's x axis, turned by the elbow's -30 deg about y.
  const Model model = test::DoublePendulum();
  const tf2_msgs::TFMessage msg = ToLinkTransforms(model, model.initial_state(), "world");
  ASSERT_EQ(msg.transforms.size(), 2u);
  const geometry_msgs::TransformStamped& link1 = msg.transforms[0];
  const geometry_msgs::TransformStamped& link2 = msg.transforms[1];
  EXPECT_EQ(link1.header.frame_id, "world");
  EXPECT_EQ(link1.child_frame_id, "link1");
  EXPECT_EQ(link2.child_frame_id, "link2");
  EXPECT_NEAR(link1.transform.translation.z, 2.0, kRoundOff);
  EXPECT_NEAR(link1.transform.rotation.w, 1.0, kRoundOff);
  EXPECT_NEAR(link2.transform.translation.x, 1.0, kRoundOff);
  EXPECT_NEAR(link2.transform.translation.y, 0.0, kRoundOff);
  EXPECT_NEAR(link2.transform.translation.z, 2.0, kRoundOff);
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(-M_PI / 6.0, Eigen::Vector3d::UnitY()));
  const geometry_msgs::Quaternion& q = link2.transform.rotation;
  EXPECT_NEAR(std::abs(expected.dot(Eigen::Quaterniond(q.w, q.x, q.y, q.z))), 1.0, kRoundOff);
}

TEST(MessageConversions, BodyMarkersSitAtTheCentresOfMassInTheLinkFrames) {
  // Reference: the URDF's <inertial> origins, (0.5, 0, 0) in link1 and (0.4, 0, 0) in link2; link1 carries
  // both joints (sticks to x = 0 and x = 1), link2 the elbow (x = 0).
  const Model model = test::DoublePendulum();
  const visualization_msgs::MarkerArray msg = ToBodyMarkers(model);
  ASSERT_EQ(msg.markers.size(), 4u);
  const visualization_msgs::Marker& link1_com = msg.markers[0];
  const visualization_msgs::Marker& link1_sticks = msg.markers[1];
  const visualization_msgs::Marker& link2_com = msg.markers[2];
  EXPECT_EQ(link1_com.header.frame_id, "link1");
  EXPECT_TRUE(link1_com.frame_locked);
  EXPECT_EQ(link1_com.type, visualization_msgs::Marker::SPHERE);
  EXPECT_NEAR(link1_com.pose.position.x, 0.5, kRoundOff);
  EXPECT_NEAR(link2_com.pose.position.x, 0.4, kRoundOff);
  ASSERT_EQ(link1_sticks.points.size(), 4u);
  std::vector<double> stick_ends{link1_sticks.points[1].x, link1_sticks.points[3].x};
  std::sort(stick_ends.begin(), stick_ends.end());
  EXPECT_NEAR(stick_ends[0], 0.0, kRoundOff);
  EXPECT_NEAR(stick_ends[1], 1.0, kRoundOff);
}

}  // namespace
}  // namespace ros
}  // namespace flexmbd
