// The node's topics and bag on the short double pendulum (test/integration/data/short_double_pendulum.yaml):
// joint_states follows the URDF, matches the runner's CSV, and the bag holds exactly what was published.
// One run serves every test: the node is started with its bag, runs as fast as it can once the recorder
// has subscribed, and is stopped with SIGINT after the last sample (it stays up with keep_alive).

#include <gtest/gtest.h>

#include <cmath>

#include "helpers/csv_table.hpp"
#include "helpers/recorded_run_suite.hpp"
#include "helpers/sample_recorder.hpp"

namespace flexmbd {
namespace test {
namespace node_topics_test {

constexpr char kNodeName[] = "flexmbd_topics";
constexpr char kUrdf[] = "config/double_pendulum/double_pendulum.urdf";
constexpr char kConfig[] = "test/integration/data/short_double_pendulum.yaml";
// The case: t_end = 2 s at 100 samples/s.
constexpr double kEndTime = 2.0;
constexpr double kSamplePeriod = 0.01;
constexpr size_t kSampleCount = 201;
// Stamps are nanoseconds.
constexpr double kStampResolution = 1.0e-9;
// The node and the runner take the same steps (the node's chunks never cut a step) and the CSV prints 17
// significant digits, so their samples agree to round-off: far below the interpolation error (~1e-4 rad).
constexpr double kSameRunTolerance = 1.0e-12;
// The joints hold to the Newton tolerance (tol = 1e-8, relative): link frames sit on the joint axes to well
// under a micrometre.
constexpr double kJointPlacementTolerance = 1.0e-6;

class NodeTopics : public RecordedRunSuite<NodeTopics> {
 public:
  static constexpr char kAwaited[] = "the topics";
  static NodeRunCase Case() {
    return {kNodeName, kUrdf, kConfig, /*record_bag=*/true,
            [](const Samples& s) { return EverySampleTopicReached(s, kEndTime); }};
  }
};

TEST_F(NodeTopics, NodeExitsWithZeroOnSigint) {
  EXPECT_EQ(record_->exit_status, std::optional<int>(0)) << record_->node_output;
}

TEST_F(NodeTopics, JointStatesNameTheUrdfJointsInOrder) {
  // Reference: config/double_pendulum/double_pendulum.urdf: shoulder (world -> link1), then elbow.
  for (const sensor_msgs::JointState& message : record_->topics.joint_states) {
    ASSERT_EQ(message.name, (std::vector<std::string>{"shoulder", "elbow"}));
    ASSERT_EQ(message.position.size(), 2u);
    ASSERT_EQ(message.velocity.size(), 2u);
    ASSERT_EQ(message.effort.size(), 2u);
  }
}

TEST_F(NodeTopics, EveryTopicDeliversEverySampleOnceInOrder) {
  // Reference: samples at t = k / rate_hz for k = 0 .. t_end * rate_hz.
  const Samples& topics = record_->topics;
  ASSERT_EQ(topics.joint_states.size(), kSampleCount);
  ASSERT_EQ(topics.energy.size(), kSampleCount);
  ASSERT_EQ(topics.reactions.size(), kSampleCount);
  ASSERT_EQ(topics.solver.size(), kSampleCount);
  for (size_t k = 0; k < kSampleCount; ++k) {
    const double t = k * kSamplePeriod;
    EXPECT_NEAR(TimeOf(topics.joint_states[k]), t, kStampResolution);
    EXPECT_NEAR(TimeOf(topics.energy[k]), t, kStampResolution);
    EXPECT_NEAR(TimeOf(topics.reactions[k]), t, kStampResolution);
    EXPECT_NEAR(TimeOf(topics.solver[k]), t, kStampResolution);
  }
}

TEST_F(NodeTopics, PositionsMatchTheRunnersCsv) {
  const CsvTable& csv = record_->csv;
  ASSERT_EQ(csv.rows.size(), kSampleCount) << "the runner did not write its CSV";
  const std::vector<sensor_msgs::JointState>& joint_states = record_->topics.joint_states;
  ASSERT_EQ(joint_states.size(), kSampleCount);
  for (size_t k = 0; k < kSampleCount; ++k) {
    const std::vector<double>& row = csv.rows[k];
    EXPECT_NEAR(TimeOf(joint_states[k]), row[csv.Column("t")], kStampResolution);
    for (size_t v = 0; v < joint_states[k].name.size(); ++v) {
      const std::string column = "joint." + joint_states[k].name[v];
      EXPECT_NEAR(joint_states[k].position[v], row[csv.Column(column + ".position")], kSameRunTolerance)
          << column << " at t = " << row[0];
      EXPECT_NEAR(joint_states[k].velocity[v], row[csv.Column(column + ".velocity")], kSameRunTolerance)
          << column << " at t = " << row[0];
    }
  }
}

TEST_F(NodeTopics, BagHoldsTheSamplesPublishedOnTopics) {
  // Reference: the messages received. Both are float64 serialised by ROS: equal bit for bit.
  const Samples& topics = record_->topics;
  const Samples& bag = record_->bag;
  EXPECT_EQ(bag.joint_states, topics.joint_states);
  EXPECT_EQ(bag.energy, topics.energy);
  EXPECT_EQ(bag.reactions, topics.reactions);
  EXPECT_EQ(bag.solver, topics.solver);
  EXPECT_EQ(bag.transforms, topics.transforms);
}

TEST_F(NodeTopics, LinkFramesStayOnTheirJoints) {
  // Reference: the URDF: link1's frame is the shoulder, fixed at (0, 0, 2) m in world; link2's frame is the
  // elbow, fixed at (1, 0, 0) m in link1 (both hinges turn about y).
  ASSERT_FALSE(record_->topics.transforms.empty());
  for (const tf2_msgs::TFMessage& message : record_->topics.transforms) {
    ASSERT_EQ(message.transforms.size(), 2u);
    const geometry_msgs::Vector3& shoulder = message.transforms[0].transform.translation;
    const geometry_msgs::Vector3& elbow = message.transforms[1].transform.translation;
    EXPECT_EQ(message.transforms[0].header.frame_id, "world");
    EXPECT_EQ(message.transforms[1].header.frame_id, "link1");
    EXPECT_NEAR(shoulder.x, 0.0, kJointPlacementTolerance);
    EXPECT_NEAR(shoulder.y, 0.0, kJointPlacementTolerance);
    EXPECT_NEAR(shoulder.z, 2.0, kJointPlacementTolerance);
    EXPECT_NEAR(elbow.x, 1.0, kJointPlacementTolerance);
    EXPECT_NEAR(elbow.y, 0.0, kJointPlacementTolerance);
    EXPECT_NEAR(elbow.z, 0.0, kJointPlacementTolerance);
  }
}

}  // namespace node_topics_test
}  // namespace test
}  // namespace flexmbd
