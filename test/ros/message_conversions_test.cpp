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
namespace message_conversions_test {

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
  sensor_msgs::JointState msg;
  FillJointState(model, sample, &msg);
  EXPECT_EQ(msg.name, (std::vector<std::string>{"shoulder", "elbow"}));
  EXPECT_EQ(msg.position, (std::vector<double>{0.1, 0.2}));
  EXPECT_EQ(msg.velocity, (std::vector<double>{1.1, 1.2}));
  EXPECT_EQ(msg.effort, (std::vector<double>{2.1, 2.2}));
}

TEST(MessageConversions, EnergyCopiesEveryTerm) {
  const Model model = test::DoublePendulum();
  Energy msg;
  FillEnergy(SampleWithDistinctValues(model), &msg);
  EXPECT_EQ(msg.kinetic, 1.5);
  EXPECT_EQ(msg.potential, 2.5);
  EXPECT_EQ(msg.external_work, 3.5);
  EXPECT_EQ(msg.dissipated, 4.5);
  EXPECT_EQ(msg.numerical_dissipation, 5.5);
}

TEST(MessageConversions, ReactionsAndSolverStepCopyTheSample) {
  const Model model = test::DoublePendulum();
  const OutputSample sample = SampleWithDistinctValues(model);
  JointReactionArray reactions;
  FillJointReactions(model, sample, &reactions);
  ASSERT_EQ(reactions.joints.size(), 2u);
  EXPECT_EQ(reactions.joints[0].joint, "shoulder");
  EXPECT_EQ(reactions.joints[1].joint, "elbow");
  EXPECT_EQ(reactions.joints[1].force.z, 6.0);
  EXPECT_EQ(reactions.joints[1].moment.x, 8.0);
  SolverStep step;
  FillSolverStep(sample, &step);
  EXPECT_EQ(step.dt, 0.003);
  EXPECT_EQ(step.iterations, 4);
}

TEST(MessageConversions, LinkTransformsGoFromTheUrdfParentLink) {
  // Reference: the URDF: link1's frame is at the shoulder (0, 0, 2) in world with the shoulder at 0 deg
  // (identity); link2's frame is at the elbow, (1, 0, 0) in link1, turned by the elbow's -30 deg about y.
  const Model model = test::DoublePendulum();
  tf2_msgs::TFMessage msg;
  FillTransforms(test::MovingFramesOf(test::kDoublePendulumUrdf, model), model.initial_state(), &msg);
  ASSERT_EQ(msg.transforms.size(), 2u);
  const geometry_msgs::TransformStamped& link1 = msg.transforms[0];
  const geometry_msgs::TransformStamped& link2 = msg.transforms[1];
  EXPECT_EQ(link1.header.frame_id, "world");
  EXPECT_EQ(link1.child_frame_id, "link1");
  EXPECT_EQ(link2.header.frame_id, "link1");
  EXPECT_EQ(link2.child_frame_id, "link2");
  EXPECT_NEAR(link1.transform.translation.z, 2.0, kRoundOff);
  EXPECT_NEAR(link1.transform.rotation.w, 1.0, kRoundOff);
  EXPECT_NEAR(link2.transform.translation.x, 1.0, kRoundOff);
  EXPECT_NEAR(link2.transform.translation.y, 0.0, kRoundOff);
  EXPECT_NEAR(link2.transform.translation.z, 0.0, kRoundOff);
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

// Hand-made stops (the loader has no backlash yet): two on one joint, one named in the YAML on another.
const std::vector<StopInfo> kStops{{"B1", "lower", 0}, {"B1", "upper", 0}, {"B2", "gear_tooth", 1}};

OutputSample SampleWithStops(size_t count, double offset) {
  OutputSample sample;
  sample.t = 2.5;
  for (size_t k = 0; k < count; ++k) {
    const double v = offset + static_cast<double>(k);
    sample.stops.push_back(StopSample{k % 2 == 1, 10.0 + v, 20.0 + v, 1.0e-6 * (v + 1.0)});
  }
  return sample;
}

TEST(MessageConversions, ContactsNameEveryStopAndCopyItsRecord) {
  // Reference: the hand-made records above, entry k from stop k.
  JointContactArray msg;
  FillJointContacts(kStops, SampleWithStops(3, 0.0), &msg);
  ASSERT_EQ(msg.contacts.size(), 3u);
  const JointContact& upper = msg.contacts[1];
  EXPECT_EQ(upper.joint, "B1");
  EXPECT_EQ(upper.stop, "upper");
  EXPECT_TRUE(upper.in_contact);
  EXPECT_EQ(upper.force, 11.0);
  EXPECT_EQ(upper.torque, 21.0);
  EXPECT_EQ(upper.approach, 2.0e-6);
  EXPECT_EQ(msg.contacts[0].stop, "lower");
  EXPECT_FALSE(msg.contacts[0].in_contact);
  EXPECT_EQ(msg.contacts[2].joint, "B2");
  EXPECT_EQ(msg.contacts[2].stop, "gear_tooth");
  EXPECT_EQ(msg.contacts[2].force, 12.0);
}

TEST(MessageConversions, RefilledContactsHoldOnlyTheNewSample) {
  // A recycled message is filled again: it must not keep entries or values of the sample it held.
  JointContactArray msg;
  FillJointContacts(kStops, SampleWithStops(3, 0.0), &msg);
  const std::vector<StopInfo> one_stop{{"B7", "upper", 0}};
  FillJointContacts(one_stop, SampleWithStops(1, 100.0), &msg);
  ASSERT_EQ(msg.contacts.size(), 1u);
  EXPECT_EQ(msg.contacts[0].joint, "B7");
  EXPECT_EQ(msg.contacts[0].stop, "upper");
  EXPECT_EQ(msg.contacts[0].force, 110.0);
}

TEST(MessageConversions, ModelWithoutStopsGivesNoContacts) {
  const Model model = test::DoublePendulum();
  JointContactArray contacts;
  FillJointContacts(model.stops(), SampleWithDistinctValues(model), &contacts);
  EXPECT_TRUE(contacts.contacts.empty());
  JointFrictionArray friction;
  FillJointFriction(model.frictions(), SampleWithDistinctValues(model), &friction);
  EXPECT_TRUE(friction.joints.empty());
}

TEST(MessageConversions, FrictionNamesEveryJointAndCopiesItsRecord) {
  // Reference: the hand-made records below, entry k from frictional joint k.
  const std::vector<FrictionInfo> frictions{{"B1", 0}, {"hinge", 2}};
  OutputSample sample;
  sample.t = 0.5;
  sample.friction.push_back(FrictionSample{true, 0.25, 12.0, 0.0, 0.125});
  sample.friction.push_back(FrictionSample{false, -0.5, 30.0, -2.0e-3, 4.0});
  JointFrictionArray msg;
  FillJointFriction(frictions, sample, &msg);
  ASSERT_EQ(msg.joints.size(), 2u);
  EXPECT_EQ(msg.joints[0].joint, "B1");
  EXPECT_TRUE(msg.joints[0].sticking);
  EXPECT_EQ(msg.joints[0].work, 0.125);
  const JointFriction& hinge = msg.joints[1];
  EXPECT_EQ(hinge.joint, "hinge");
  EXPECT_FALSE(hinge.sticking);
  EXPECT_EQ(hinge.torque, -0.5);
  EXPECT_EQ(hinge.normal_force, 30.0);
  EXPECT_EQ(hinge.slip_velocity, -2.0e-3);
  EXPECT_EQ(hinge.work, 4.0);
}

TEST(MessageConversions, BeamNodeFramesSitOnTheCentreLineUnderTheBeamLink) {
  // Reference: test/data beam_arm: the beam link 'arm' clamped at (0, 0, 1) m in world (rpy 0), 2 cubic
  // elements: node k at x = k / 6 m in the beam link's frame, with its axes; the tip body's link frame at the
  // hinge, (1, 0, 0) in arm.
  const Model model = test::BeamArm();
  tf2_msgs::TFMessage msg;
  FillTransforms(test::MovingFramesOf(test::kBeamArmUrdf, model), model.initial_state(), &msg);
  ASSERT_EQ(msg.transforms.size(), 9u);
  EXPECT_EQ(msg.transforms[0].header.frame_id, "world");
  EXPECT_EQ(msg.transforms[0].child_frame_id, "arm");
  EXPECT_NEAR(msg.transforms[0].transform.translation.z, 1.0, kRoundOff);
  for (size_t k = 0; k < 7; ++k) {
    const geometry_msgs::TransformStamped& node = msg.transforms[1 + k];
    EXPECT_EQ(node.child_frame_id, "arm/node_" + std::to_string(k));
    EXPECT_EQ(node.header.frame_id, "arm");
    EXPECT_NEAR(node.transform.translation.x, k / 6.0, kRoundOff) << node.child_frame_id;
    EXPECT_NEAR(node.transform.translation.y, 0.0, kRoundOff) << node.child_frame_id;
    EXPECT_NEAR(node.transform.translation.z, 0.0, kRoundOff) << node.child_frame_id;
    EXPECT_NEAR(std::abs(node.transform.rotation.w), 1.0, kRoundOff) << node.child_frame_id;
  }
  EXPECT_EQ(msg.transforms[8].header.frame_id, "arm");
  EXPECT_EQ(msg.transforms[8].child_frame_id, "tip");
  EXPECT_NEAR(msg.transforms[8].transform.translation.x, 1.0, kRoundOff);
  EXPECT_NEAR(msg.transforms[8].transform.translation.z, 0.0, kRoundOff);
}

TEST(MessageConversions, BeamNodeFramesFollowTheDeformedNodes) {
  // A node moved and turned in the state moves its frame relative to the beam link (the root node's frame,
  // left at (0, 0, 1) m with the world axes): the frame is the node's pose itself, less the root's.
  const Model model = test::BeamArm();
  State state = model.initial_state();
  const int tip_node = model.beams()[0].nodes.back();
  state.nodes[tip_node].x = Vec3(0.9, 0.3, 1.1);
  state.nodes[tip_node].R = Eigen::AngleAxisd(0.4, Vec3::UnitZ()).toRotationMatrix();
  tf2_msgs::TFMessage msg;
  FillTransforms(test::MovingFramesOf(test::kBeamArmUrdf, model), state, &msg);
  const geometry_msgs::TransformStamped& tip = msg.transforms[7];
  EXPECT_EQ(tip.child_frame_id, "arm/node_6");
  EXPECT_NEAR(tip.transform.translation.y, 0.3, kRoundOff);
  EXPECT_NEAR(tip.transform.translation.z, 0.1, kRoundOff);
  EXPECT_NEAR(tip.transform.rotation.z, std::sin(0.2), kRoundOff);
}

TEST(MessageConversions, BeamNodeMarkersRideOnTheNodeFrames) {
  const Model model = test::BeamArm();
  const visualization_msgs::MarkerArray msg = ToBodyMarkers(model);
  std::vector<std::string> frames;
  for (const visualization_msgs::Marker& marker : msg.markers) {
    if (marker.ns != "beam_nodes") continue;
    EXPECT_TRUE(marker.frame_locked);
    EXPECT_EQ(marker.type, visualization_msgs::Marker::SPHERE);
    frames.push_back(marker.header.frame_id);
  }
  ASSERT_EQ(frames.size(), 7u);
  EXPECT_EQ(frames.front(), "arm/node_0");
  EXPECT_EQ(frames.back(), "arm/node_6");
}

}  // namespace message_conversions_test
}  // namespace ros
}  // namespace flexmbd
