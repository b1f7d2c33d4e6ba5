// SampleConverter (include/flexmbd/ros/sample_converter.hpp): one conversion per sample, and link transforms
// once per state, stamped with the state's own time.

#include "flexmbd/ros/sample_converter.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "flexmbd/solver/simulation.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace {

// ros::Time keeps nanoseconds.
constexpr double kStampResolution = 1.0e-9;

TEST(SampleConverter, SendsTransformsOncePerStateAtTheStateTime) {
  // Two samples interpolated inside one step share its end state: the second carries no transforms.
  const Model model = test::DoublePendulum();
  SampleConverter converter(model, "world");
  State state = model.initial_state();
  OutputSample sample;
  sample.position = sample.velocity = sample.effort = Eigen::VectorXd::Zero(model.num_variables());
  sample.reaction_force_W = sample.reaction_moment = std::vector<Vec3>(model.joints().size(), Vec3::Zero());

  state.t = 0.02;
  sample.t = 0.01;
  const SampleMessages first = converter.Convert(sample, state);
  ASSERT_TRUE(first.transforms.has_value());
  EXPECT_NEAR(first.transforms->transforms[0].header.stamp.toSec(), 0.02, kStampResolution);
  EXPECT_NEAR(first.joint_state.header.stamp.toSec(), 0.01, kStampResolution);

  sample.t = 0.015;
  EXPECT_FALSE(converter.Convert(sample, state).transforms.has_value());

  state.t = 0.03;
  sample.t = 0.025;
  EXPECT_TRUE(converter.Convert(sample, state).transforms.has_value());
}

TEST(SampleConverter, TransformStampsBracketEverySampleOfARun) {
  // Reference: the design rule on SampleMessages::transforms: for each sample there is a transform stamped at
  // or before it and one at the end of its step (at most dt_max later), so tf interpolates the link frames at
  // every sample time over no more than one step.
  const Model model = test::DoublePendulum();
  SampleConverter converter(model, "world");
  Simulation simulation(model);
  std::vector<double> sample_times, transform_times;
  simulation.Run([&](const OutputSample& sample) {
    const SampleMessages messages = converter.Convert(sample, simulation.state());
    sample_times.push_back(messages.joint_state.header.stamp.toSec());
    if (messages.transforms) transform_times.push_back(messages.transforms->transforms[0].header.stamp.toSec());
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

}  // namespace
}  // namespace ros
}  // namespace flexmbd
