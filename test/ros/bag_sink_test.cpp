// BagSink (include/flexmbd/ros/bag_sink.hpp): every sample recorded losslessly, readable after Close.

#include "flexmbd/ros/bag_sink.hpp"

#include <gtest/gtest.h>
#include <rosbag/view.h>

#include "../integration/helpers/file_size_limit.hpp"
#include "flexmbd/common/error.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace bag_sink_test {

template <typename Message>
std::vector<Message> ReadTopic(const std::string& path, const std::string& topic) {
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  std::vector<Message> messages;
  for (const rosbag::MessageInstance& instance : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    messages.push_back(*instance.instantiate<Message>());
  }
  return messages;
}

// Records the first second of the double pendulum and returns what was written.
std::vector<SampleMessages> RecordDoublePendulum(const std::string& path, BagCompression compression) {
  const Model model = test::DoublePendulum();
  SampleConverter converter(model, test::FramesOf(test::kDoublePendulumUrdf, model));
  Simulation simulation(model);
  std::vector<SampleMessages> written;
  BagSink bag(path, compression, DefaultTopicNames(), ToBodyMarkers(model), tf2_msgs::TFMessage());
  const Simulation::SampleSink convert = [&](const OutputSample& sample) {
    written.emplace_back();
    converter.Convert(sample, simulation.state(), &written.back());
  };
  simulation.Begin(convert);
  simulation.AdvanceTo(1.0, model.solver().t_end, convert);
  for (const SampleMessages& messages : written) bag.Write(messages);
  bag.Close();
  return written;
}

void ExpectBagHolds(const std::string& path, const std::vector<SampleMessages>& written) {
  const TopicNames topics = DefaultTopicNames();
  const auto joint_states = ReadTopic<sensor_msgs::JointState>(path, topics.joint_states);
  const auto energy = ReadTopic<Energy>(path, topics.energy);
  const auto reactions = ReadTopic<JointReactionArray>(path, topics.reactions);
  const auto solver = ReadTopic<SolverStep>(path, topics.solver);
  ASSERT_EQ(joint_states.size(), written.size());
  ASSERT_EQ(energy.size(), written.size());
  ASSERT_EQ(reactions.size(), written.size());
  ASSERT_EQ(solver.size(), written.size());
  for (size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(joint_states[k], written[k].joint_state) << "sample " << k;
    EXPECT_EQ(energy[k], written[k].energy) << "sample " << k;
    EXPECT_EQ(reactions[k], written[k].reactions) << "sample " << k;
    EXPECT_EQ(solver[k], written[k].solver) << "sample " << k;
  }
  EXPECT_EQ(ReadTopic<visualization_msgs::MarkerArray>(path, topics.markers).size(), 1u);
}

TEST(BagSink, HoldsEverySampleExactly) {
  // Reference: the messages written; float64 fields and the bag's serialisation are exact.
  const std::string path = testing::TempDir() + "bag_sink_plain.bag";
  const std::vector<SampleMessages> written = RecordDoublePendulum(path, BagCompression::kNone);
  ASSERT_EQ(written.size(), 101u);  // t = 0, 0.01, ..., 1 s at 100 samples/s
  ExpectBagHolds(path, written);
  // the double pendulum has no stops, no friction, no beam stations and no aero sections: no such topics
  EXPECT_TRUE(ReadTopic<JointContactArray>(path, DefaultTopicNames().contacts).empty());
  EXPECT_TRUE(ReadTopic<JointFrictionArray>(path, DefaultTopicNames().friction).empty());
  EXPECT_TRUE(ReadTopic<BeamLoadsArray>(path, DefaultTopicNames().beam_loads).empty());
  EXPECT_TRUE(ReadTopic<AeroLoadsArray>(path, DefaultTopicNames().aero_loads).empty());
}

TEST(BagSink, RecordsTheStaticTransformsOnceAsLatched) {
  // Reference: the antenna's URDF: its massless bus is fixed to the world; rosbag play latches a topic whose
  // connection header says latching=1, as rosbag record writes it for a latched publisher.
  const std::string path = testing::TempDir() + "bag_sink_static.bag";
  const Model model = BuildModel(LoadModelSpec(test::SourcePath("config/antenna/antenna.urdf"),
                                               test::SourcePath("config/antenna/antenna_dampers.yaml")));
  const tf2_msgs::TFMessage fixed = ToStaticTransforms(test::FramesOf("config/antenna/antenna.urdf", model).fixed);
  BagSink(path, BagCompression::kNone, DefaultTopicNames(), ToBodyMarkers(model), fixed).Close();
  ASSERT_EQ(fixed.transforms.size(), 1u);
  EXPECT_EQ(fixed.transforms[0].child_frame_id, "bus");
  EXPECT_EQ(ReadTopic<tf2_msgs::TFMessage>(path, DefaultTopicNames().tf_static),
            std::vector<tf2_msgs::TFMessage>{fixed});
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  for (const rosbag::MessageInstance& instance : rosbag::View(bag, rosbag::TopicQuery(DefaultTopicNames().tf_static))) {
    EXPECT_EQ(instance.getConnectionHeader()->at("latching"), "1");
  }
}

TEST(BagSink, RecordsContactsAndFrictionOfEverySample) {
  // Reference: hand-made stop and friction records (the loader has no backlash or friction yet), written
  // through the conversion the converter uses and read back exactly.
  const std::string path = testing::TempDir() + "bag_sink_contacts.bag";
  const Model model = test::DoublePendulum();
  const std::vector<StopInfo> stops{{"shoulder", "lower", 0}, {"shoulder", "upper", 0}};
  const std::vector<FrictionInfo> frictions{{"elbow", 1}};
  std::vector<SampleMessages> written(3);
  {
    BagSink bag(path, BagCompression::kNone, DefaultTopicNames(), ToBodyMarkers(model), tf2_msgs::TFMessage());
    for (size_t k = 0; k < written.size(); ++k) {
      OutputSample sample;
      sample.t = 0.1 * static_cast<double>(k);
      sample.stops = {StopSample{false, 0.0, 0.0, 0.0}, StopSample{k > 0, 5.0 * k, -2.5 * k, 1.0e-5 * k}};
      sample.friction = {FrictionSample{k == 1, 0.1 * k, 3.0, 0.01 * k, 0.002 * k}};
      FillJointContacts(stops, sample, &written[k].contacts);
      FillJointFriction(frictions, sample, &written[k].friction);
      written[k].contacts.header.seq = written[k].friction.header.seq = static_cast<uint32_t>(k);
      bag.Write(written[k]);
    }
  }
  const auto contacts = ReadTopic<JointContactArray>(path, DefaultTopicNames().contacts);
  const auto friction = ReadTopic<JointFrictionArray>(path, DefaultTopicNames().friction);
  ASSERT_EQ(contacts.size(), written.size());
  ASSERT_EQ(friction.size(), written.size());
  for (size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(contacts[k], written[k].contacts) << "sample " << k;
    EXPECT_EQ(friction[k], written[k].friction) << "sample " << k;
  }
  EXPECT_EQ(contacts[2].contacts[1].stop, "upper");
  EXPECT_EQ(contacts[2].contacts[1].force, 10.0);
}

TEST(BagSink, Lz4BagHoldsTheSameSamples) {
  const std::string path = testing::TempDir() + "bag_sink_lz4.bag";
  ExpectBagHolds(path, RecordDoublePendulum(path, BagCompression::kLz4));
}

TEST(BagSink, FirstSampleAtTimeZeroIsRecordedAtTheEarliestBagTime) {
  // rosbag refuses time 0: the t = 0 sample is recorded at ros::TIME_MIN and keeps its stamp.
  const std::string path = testing::TempDir() + "bag_sink_time.bag";
  RecordDoublePendulum(path, BagCompression::kNone);
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  rosbag::View view(bag, rosbag::TopicQuery(DefaultTopicNames().joint_states));
  const rosbag::MessageInstance first = *view.begin();
  EXPECT_EQ(first.getTime(), ::ros::TIME_MIN);
  EXPECT_EQ(first.instantiate<sensor_msgs::JointState>()->header.stamp, ::ros::Time(0.0));
}

// The message of the `Error` that creating a bag at `path` throws, or a note that it threw none.
template <typename Error>
std::string OpenErrorOf(const std::string& path) {
  const Model model = test::DoublePendulum();
  try {
    BagSink bag(path, BagCompression::kNone, DefaultTopicNames(), ToBodyMarkers(model), tf2_msgs::TFMessage());
  } catch (const Error& error) {
    return error.what();
  }
  return "(none thrown)";
}

TEST(BagSink, UnwritablePathIsAConfigErrorNamingIt) {
  const std::string message = OpenErrorOf<ConfigError>("/nonexistent_dir/run.bag");
  EXPECT_NE(message.find("cannot open bag '/nonexistent_dir/run.bag' for writing"), std::string::npos) << message;
  EXPECT_NE(message.find("expected a writable file path"), std::string::npos) << message;
}

TEST(BagSink, FullDeviceIsAnOutputErrorNamingIt) {
  // /dev/full opens but takes no byte: an output failure (exit 3), not a bad path (exit 2), and no abort.
  const std::string message = OpenErrorOf<OutputError>("/dev/full");
  EXPECT_EQ(message.find("bag '/dev/full': writing failed after 0 samples ("), 0u) << message;
  EXPECT_NE(message.find("No space left on device); the bag holds no sample"), std::string::npos) << message;
}

TEST(BagSink, DiskFullMidRunIsAnOutputErrorCountingTheSamplesRecorded) {
  // A 100 kB cap (RLIMIT_FSIZE) against the double pendulum's samples written over and over: Write throws,
  // and the sink (and its rosbag::Bag, whose close would throw again) is destroyed without terminating.
  const std::string path = testing::TempDir() + "bag_sink_capped.bag";
  const std::vector<SampleMessages> samples = RecordDoublePendulum(path, BagCompression::kNone);
  const Model model = test::DoublePendulum();
  std::string message;
  long recorded = 0;
  {
    const test::FileSizeLimit cap(100000);
    BagSink bag(path, BagCompression::kNone, DefaultTopicNames(), ToBodyMarkers(model), tf2_msgs::TFMessage());
    try {
      for (; recorded < 100000; ++recorded) bag.Write(samples[recorded % samples.size()]);
    } catch (const OutputError& error) {
      message = error.what();
    }
    EXPECT_NO_THROW(bag.Close());  // the failure was reported once
  }
  ASSERT_LT(recorded, 100000) << "the cap did not stop the bag";
  EXPECT_EQ(message.find("bag '" + path + "': writing failed after " + std::to_string(recorded) + " samples ("), 0u)
      << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_NE(message.find("'rosbag reindex " + path + "'"), std::string::npos) << message;
}

TEST(BagSink, ParsesTheCompressionNames) {
  EXPECT_EQ(ParseBagCompression("none"), BagCompression::kNone);
  EXPECT_EQ(ParseBagCompression("lz4"), BagCompression::kLz4);
  EXPECT_FALSE(ParseBagCompression("bz2").has_value());
}

}  // namespace bag_sink_test
}  // namespace ros
}  // namespace flexmbd
