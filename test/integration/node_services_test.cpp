// The node's services (std_srvs/Trigger): ~pause stops the samples, ~step sends exactly the next one,
// ~resume goes on without gap or repeat, ~reset starts again from the initial state. Each test starts its
// own node on the short double pendulum (100 samples/s, t_end = 2 s) and subscribes before it starts.

#include <gtest/gtest.h>
#include <std_srvs/Trigger.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "helpers/node_process.hpp"
#include "helpers/sample_recorder.hpp"

namespace flexmbd {
namespace test {
namespace node_services_test {

constexpr char kNodeName[] = "flexmbd_services";
constexpr double kSamplePeriod = 0.01;
constexpr double kEndTime = 2.0;
// Stamps are nanoseconds; the replies print times with 17 significant digits.
constexpr double kStampResolution = 1.0e-9;
// Bound on start-up and message delivery on a loaded 2-core machine; met in milliseconds.
constexpr std::chrono::seconds kDeliveryTimeout(30);
// Window in which a paused node must send nothing: at real-time pace a node that ignored the pause would
// send about 30 samples in it.
constexpr std::chrono::milliseconds kQuietWindow(300);

// The time a reply names, "... the sample at t = <t> s ...".
double TimeInReply(const std::string& message) {
  std::smatch match;
  if (!std::regex_search(message, match, std::regex("t = ([-+0-9.eE]+) s"))) return -1.0;
  return std::stod(match[1]);
}

class NodeServices : public testing::Test {
 protected:
  /// Starts the node paced at `real_time_factor`; it waits for the recorder before its first sample.
  void StartNode(double real_time_factor) {
    recorder_ = std::make_unique<SampleRecorder>(kNodeName);
    node_ = std::make_unique<NodeProcess>(
        kNodeName, std::vector<std::string>{"_real_time_factor:=" + std::to_string(real_time_factor),
                                            "_wait_for_subscribers:=1", "_keep_alive:=true"});
    ASSERT_TRUE(::ros::service::waitForService(std::string("/") + kNodeName + "/pause",
                                               ::ros::Duration(kDeliveryTimeout.count())))
        << node_->Output();
  }

  void TearDown() override {
    if (node_) {
      node_->Interrupt();
      EXPECT_EQ(node_->WaitForExit(kDeliveryTimeout), std::optional<int>(0)) << node_->Output();
    }
  }

  std_srvs::Trigger::Response Call(const std::string& service) {
    std_srvs::Trigger trigger;
    EXPECT_TRUE(::ros::service::call(std::string("/") + kNodeName + "/" + service, trigger)) << service;
    return trigger.response;
  }

  /// Waits until joint_states has delivered a sample stamped `t`.
  bool WaitForSampleAt(double t) {
    return recorder_->WaitUntil(
        [t](const Samples& s) {
          return std::any_of(s.joint_states.begin(), s.joint_states.end(),
                             [t](const auto& m) { return std::abs(TimeOf(m) - t) < kStampResolution; });
        },
        kDeliveryTimeout);
  }

  /// True if a joint_states sample later than `t` arrives within the quiet window.
  bool SampleAfterArrives(double t) {
    return recorder_->WaitUntil(
        [t](const Samples& s) {
          return !s.joint_states.empty() && TimeOf(s.joint_states.back()) > t + kStampResolution;
        },
        kQuietWindow);
  }

  std::unique_ptr<SampleRecorder> recorder_;
  std::unique_ptr<NodeProcess> node_;
};

TEST_F(NodeServices, PauseStopsTheSamplesAfterTheOneItNames) {
  StartNode(1.0);
  ASSERT_TRUE(recorder_->WaitForTime(0.1, kDeliveryTimeout));
  const std_srvs::Trigger::Response paused = Call("pause");
  ASSERT_TRUE(paused.success) << paused.message;
  const double t_paused = TimeInReply(paused.message);
  ASSERT_GE(t_paused, 0.1) << paused.message;
  EXPECT_TRUE(WaitForSampleAt(t_paused));
  EXPECT_FALSE(SampleAfterArrives(t_paused));
}

TEST_F(NodeServices, StepSendsExactlyTheNextSample) {
  StartNode(1.0);
  ASSERT_TRUE(recorder_->WaitForTime(0.05, kDeliveryTimeout));
  const double t_paused = TimeInReply(Call("pause").message);
  for (int k = 1; k <= 2; ++k) {
    const std_srvs::Trigger::Response stepped = Call("step");
    ASSERT_TRUE(stepped.success) << stepped.message;
    const double t_step = TimeInReply(stepped.message);
    EXPECT_NEAR(t_step, t_paused + k * kSamplePeriod, kStampResolution) << stepped.message;
    EXPECT_TRUE(WaitForSampleAt(t_step));
    EXPECT_FALSE(SampleAfterArrives(t_step));
  }
}

TEST_F(NodeServices, ResumeGoesOnWithoutGapOrRepeat) {
  StartNode(1.0);
  ASSERT_TRUE(recorder_->WaitForTime(0.05, kDeliveryTimeout));
  const double t_paused = TimeInReply(Call("pause").message);
  EXPECT_FALSE(SampleAfterArrives(t_paused));
  const std_srvs::Trigger::Response resumed = Call("resume");
  ASSERT_TRUE(resumed.success) << resumed.message;
  ASSERT_TRUE(recorder_->WaitForTime(t_paused + 0.1, kDeliveryTimeout));
  const Samples samples = recorder_->Snapshot();
  for (size_t k = 0; k < samples.joint_states.size(); ++k) {
    EXPECT_NEAR(TimeOf(samples.joint_states[k]), k * kSamplePeriod, kStampResolution) << "sample " << k;
  }
}

TEST_F(NodeServices, ResetStartsAgainFromTheInitialState) {
  // Reference: the first sample of the run (t = 0). The run is deterministic, so the restarted one repeats it
  // (all but header.seq, which roscpp counts on over the reset).
  StartNode(1.0);
  ASSERT_TRUE(recorder_->WaitForTime(0.1, kDeliveryTimeout));
  const double t_paused = TimeInReply(Call("pause").message);
  ASSERT_TRUE(recorder_->WaitForTime(t_paused, kDeliveryTimeout));
  const size_t before_reset = recorder_->Snapshot().joint_states.size();
  const std_srvs::Trigger::Response reset = Call("reset");
  ASSERT_TRUE(reset.success) << reset.message;
  EXPECT_EQ(TimeInReply(reset.message), 0.0) << reset.message;
  const std_srvs::Trigger::Response stepped = Call("step");
  EXPECT_EQ(TimeInReply(stepped.message), 0.0) << stepped.message;
  ASSERT_TRUE(recorder_->WaitUntil(
      [&](const Samples& s) { return s.joint_states.size() > before_reset && s.energy.size() > before_reset; },
      kDeliveryTimeout));
  Samples samples = recorder_->Snapshot();
  ASSERT_EQ(samples.energy.size(), samples.joint_states.size());
  samples.joint_states[before_reset].header.seq = samples.energy[before_reset].header.seq = 0;
  EXPECT_EQ(samples.joint_states[before_reset], samples.joint_states.front());
  EXPECT_EQ(samples.energy[before_reset], samples.energy.front());
}

TEST_F(NodeServices, StepPauseOrResumeAfterTheEndFailsAndResetRunsAgain) {
  StartNode(0.0);
  ASSERT_TRUE(recorder_->WaitForTime(kEndTime, kDeliveryTimeout));
  for (const char* service : {"step", "pause", "resume"}) {
    const std_srvs::Trigger::Response answer = Call(service);
    EXPECT_FALSE(answer.success) << service;
    EXPECT_NE(answer.message.find("the run has ended"), std::string::npos) << service << ": " << answer.message;
  }
  const size_t first_run = recorder_->Snapshot().joint_states.size();
  ASSERT_TRUE(Call("reset").success);
  ASSERT_TRUE(
      recorder_->WaitUntil([&](const Samples& s) { return s.joint_states.size() == 2 * first_run; }, kDeliveryTimeout));
  EXPECT_NEAR(TimeOf(recorder_->Snapshot().joint_states.back()), kEndTime, kStampResolution);
}

}  // namespace node_services_test
}  // namespace test
}  // namespace flexmbd
