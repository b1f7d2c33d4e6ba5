// SampleConverter (include/flexmbd/ros/sample_converter.hpp): one conversion per sample, and link transforms
// once per state, stamped with the state's own time.

#include "flexmbd/ros/sample_converter.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "flexmbd/solver/simulation.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace sample_converter_test {

// ros::Time keeps nanoseconds.
constexpr double kStampResolution = 1.0e-9;

TEST(SampleConverter, SendsTransformsOncePerStateAtTheStateTime) {
  // Two samples interpolated inside one step share its end state: the second carries no transforms.
  const Model model = test::DoublePendulum();
  SampleConverter converter(model, test::FramesOf(test::kDoublePendulumUrdf, model));
  State state = model.initial_state();
  OutputSample sample;
  sample.position = sample.velocity = sample.effort = Eigen::VectorXd::Zero(model.num_variables());
  sample.reaction_force_W = sample.reaction_moment = std::vector<Vec3>(model.joints().size(), Vec3::Zero());

  state.t = 0.02;
  sample.t = 0.01;
  SampleMessages messages;
  converter.Convert(sample, state, &messages);
  ASSERT_TRUE(messages.has_transforms);
  EXPECT_NEAR(messages.transforms.transforms[0].header.stamp.toSec(), 0.02, kStampResolution);
  EXPECT_NEAR(messages.joint_state.header.stamp.toSec(), 0.01, kStampResolution);
  EXPECT_EQ(messages.reactions.header.frame_id, "world");  // the URDF's ground root link

  sample.t = 0.015;
  converter.Convert(sample, state, &messages);  // refilled: the flag of the previous sample must not stay
  EXPECT_FALSE(messages.has_transforms);

  state.t = 0.03;
  sample.t = 0.025;
  converter.Convert(sample, state, &messages);
  EXPECT_TRUE(messages.has_transforms);
}

TEST(SampleConverter, TransformStampsBracketEverySampleOfARun) {
  // Reference: the design rule on SampleMessages::transforms: for each sample there is a transform stamped at
  // or before it and one at the end of its step (at most dt_max later), so tf interpolates the link frames at
  // every sample time over no more than one step.
  const Model model = test::DoublePendulum();
  SampleConverter converter(model, test::FramesOf(test::kDoublePendulumUrdf, model));
  Simulation simulation(model);
  std::vector<double> sample_times, transform_times;
  simulation.Run([&](const OutputSample& sample) {
    SampleMessages messages;
    converter.Convert(sample, simulation.state(), &messages);
    sample_times.push_back(messages.joint_state.header.stamp.toSec());
    if (messages.has_transforms) transform_times.push_back(messages.transforms.transforms[0].header.stamp.toSec());
  });
  ASSERT_GT(sample_times.size(), 100u);
  ASSERT_TRUE(std::is_sorted(transform_times.begin(), transform_times.end()));
  const double dt_max = model.solver().dt_max;
  for (double t : sample_times) {
    EXPECT_LE(transform_times.front(), t + kStampResolution) << "no transform at or before t = " << t;
    const auto after = std::lower_bound(transform_times.begin(), transform_times.end(), t - kStampResolution);
    ASSERT_NE(after, transform_times.end()) << "no transform at or after t = " << t;
    EXPECT_LE(*after - t, dt_max + kStampResolution) << "t = " << t;
  }
}

TEST(SampleConverter, HeadersCarryTheSampleIndexAndTime) {
  // Reference: header.seq = the sample's index in the run and header.stamp its time, the same on every
  // sample topic (docs/ros.md).
  // the beam arm with one station, sampled at every step of its first 3 ms (a few steps: the beam is slow to
  // step)
  ModelSpec spec = LoadModelSpec(test::SourcePath(test::kBeamArmUrdf),
                                 test::SourcePath("test/data/yaml/beam_arm.yaml"));
  spec.output.rate_hz = 0.0;
  spec.output.beam_stations["arm"] = {0.5};
  spec.solver.t_end = 3.0e-3;
  const Model model = BuildModel(spec);
  SampleConverter converter(model, test::FramesOf(test::kBeamArmUrdf, model));
  Simulation simulation(model);
  std::vector<SampleMessages> converted;
  std::vector<double> times;
  simulation.Run([&](const OutputSample& sample) {
    converted.emplace_back();
    converter.Convert(sample, simulation.state(), &converted.back());
    times.push_back(sample.t);
  });
  ASSERT_GT(converted.size(), 2u);
  for (uint32_t k = 0; k < converted.size(); ++k) {
    const SampleMessages& messages = converted[k];
    for (const std_msgs::Header* header :
         {&messages.joint_state.header, &messages.energy.header, &messages.reactions.header, &messages.solver.header,
          &messages.contacts.header, &messages.friction.header, &messages.beam_loads.header}) {
      EXPECT_EQ(header->seq, k);
      EXPECT_NEAR(header->stamp.toSec(), times[k], kStampResolution) << "sample " << k;
    }
  }
  EXPECT_GT(times.back(), 0.0);
  ASSERT_EQ(converted.back().beam_loads.stations.size(), 1u);
  EXPECT_EQ(converted.back().beam_loads.stations[0].beam, "arm");
  // the beam's link frame, its 7 node frames and the tip's link frame, every step
  ASSERT_TRUE(converted.back().has_transforms);
  EXPECT_EQ(converted.back().transforms.transforms.size(), 9u);
}

}  // namespace sample_converter_test
}  // namespace ros
}  // namespace flexmbd
