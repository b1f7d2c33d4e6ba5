// How the node ends (src/nodes/flexmbd_node.cpp): bad input -> exit 2 with one line naming the parameter or
// file and the expected form; SIGINT in the middle of a run -> exit 0 with a readable bag holding every
// sample so far; a solver failure -> exit 3 with a readable bag; a bag or CSV write that fails (a full disk:
// /dev/full, or a file size cap) -> exit 3 with one line naming the file, never an abort.

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "helpers/bag_samples.hpp"
#include "helpers/file_size_limit.hpp"
#include "helpers/node_process.hpp"
#include "helpers/sample_recorder.hpp"
#include "helpers/temp_dir.hpp"

namespace flexmbd {
namespace test {
namespace node_exit_test {

constexpr int kBadInputExit = 2;
constexpr int kRunFailedExit = 3;
constexpr double kSamplePeriod = 0.01;
constexpr double kEndTime = 2.0;
// Stamps are nanoseconds.
constexpr double kStampResolution = 1.0e-9;
// Bound on start-up, loading and shutdown on a loaded 2-core machine; met in well under a second.
constexpr std::chrono::seconds kTimeout(30);

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A node started with `arguments` exits with 2 and its output holds `message`: one line naming the parameter
// or file and the expected form.
void ExpectBadInputExit(const std::string& name, const std::vector<std::string>& arguments,
                        const std::string& message) {
  NodeProcess node(name, arguments);
  EXPECT_EQ(node.WaitForExit(kTimeout), std::optional<int>(kBadInputExit));
  EXPECT_TRUE(Contains(node.Output(), message)) << node.Output();
}

TEST(NodeExit, BadParameterExitsWithTwoNamingTheParameter) {
  // Reference: docs/config.md, "Errors": the loader's message, with the node's namespace as its source.
  ExpectBadInputExit("flexmbd_bad_param", {},
                     "/flexmbd_bad_param: joints.elbow.spring.k: -3 is negative; "
                     "expected a stiffness >= 0 [N m/rad]");
}

TEST(NodeExit, BadNodeSettingExitsWithTwoNamingTheSetting) {
  ExpectBadInputExit("flexmbd_bad_setting", {"_real_time_factor:=-1.0"},
                     "/flexmbd_bad_setting/real_time_factor: '-1' is not a finite number >= 0; "
                     "expected a factor >= 0 (0 = as fast as possible, 1 = wall-clock pace)");
}

TEST(NodeExit, ZeroSetpointTimeConstantExitsWithTwoNamingTheSetting) {
  // Reference: docs/ros.md, Inputs: a drive cannot follow its set-point with no lag (a jump in one step).
  ExpectBadInputExit("flexmbd_bad_lag", {"_setpoint_time_constant:=0.0"},
                     "/flexmbd_bad_lag/setpoint_time_constant: '0' is not > 0; expected a time constant > 0 [s] "
                     "(the lag of a drive behind ~position_command)");
}

TEST(NodeExit, MisspeltNodeSettingExitsWithTwoListingTheSettings) {
  // Reference: src/ros/node_case.cpp: a private name that is no setting and no YAML section is named with the
  // nearest setting and both lists (the loader's message listed only the sections).
  ExpectBadInputExit("flexmbd_misspelt_setting", {"_realtime_factor:=2.0"},
                     "/flexmbd_misspelt_setting/realtime_factor: unknown parameter; did you mean "
                     "'real_time_factor'? expected a node setting (urdf_file, real_time_factor, bag, "
                     "bag_compression, publish, rate_hz, keep_alive, wait_for_subscribers, "
                     "wait_for_subscribers_timeout, clock_rate_hz, paused, "
                     "setpoint_time_constant) "
                     "or a section of the case (beams, joints, solver, output, loads, aero, closures, docs/config.md)");
}

TEST(NodeExit, StopOutsideTheUrdfLimitIsLoggedAsAWarningAndTheRunEndsWithZero) {
  // Reference: docs/config.md, "URDF mapping": the loader's warning (the runner prints it on stderr), as ROS_WARN.
  NodeProcess node("flexmbd_stop_warning", {});
  EXPECT_EQ(node.WaitForExit(kTimeout), std::optional<int>(0)) << node.Output();
  EXPECT_TRUE(Contains(node.Output(), "flexmbd: /flexmbd_stop_warning: joints.elbow.backlash.upper: 30 [rad] is "
                                      "outside the URDF <limit> [-3.14, 3.14] [rad] of joint 'elbow': this stop, not "
                                      "the <limit>, bounds the motion; if 30 is in degrees, write upper_deg: 30"))
      << node.Output();
  EXPECT_TRUE(Contains(node.Output(), "[ WARN]")) << node.Output();
}

TEST(NodeExit, MissingUrdfFileExitsWithTwoNamingTheFile) {
  ExpectBadInputExit("flexmbd_missing_urdf", {"_urdf_file:=/nonexistent/arm.urdf"},
                     "cannot open URDF file '/nonexistent/arm.urdf': No such file or directory");
}

TEST(NodeExit, SigintMidRunLeavesAReadableBagWithEverySampleSoFar) {
  // Reference: the samples received on topics before the interrupt; the bag must hold them and continue the
  // sequence t = k / rate_hz without gaps, and end before t_end (the run was cut short).
  const TempDir dir("flexmbd_node_exit");
  const std::string bag = dir.File("interrupted.bag");
  SampleRecorder recorder("flexmbd_interrupted");
  NodeProcess node("flexmbd_interrupted", {"_bag:=" + bag, "_real_time_factor:=1.0", "_wait_for_subscribers:=1"});
  ASSERT_TRUE(recorder.WaitForTime(0.3, kTimeout)) << node.Output();
  node.Interrupt();
  ASSERT_EQ(node.WaitForExit(kTimeout), std::optional<int>(0)) << node.Output();
  EXPECT_EQ(std::system(("rosbag info " + bag + " > /dev/null").c_str()), 0) << "rosbag info cannot read " << bag;

  const Samples recorded = ReadBagSamples(bag, "flexmbd_interrupted");
  const Samples received = recorder.Snapshot();
  ASSERT_GE(recorded.joint_states.size(), received.joint_states.size());
  for (size_t k = 0; k < recorded.joint_states.size(); ++k) {
    EXPECT_NEAR(TimeOf(recorded.joint_states[k]), k * kSamplePeriod, kStampResolution) << "sample " << k;
  }
  for (size_t k = 0; k < received.joint_states.size(); ++k) {
    EXPECT_EQ(recorded.joint_states[k], received.joint_states[k]) << "sample " << k;
  }
  EXPECT_EQ(recorded.energy.size(), recorded.joint_states.size());
  EXPECT_LT(TimeOf(recorded.joint_states.back()), kEndTime);
}

TEST(NodeExit, SolverFailureExitsWithThreeAndClosesTheBag) {
  // Reference: test/integration/data/failing_run.yaml fails once the error estimate has its three steps of
  // history, with the step below dt_min. Its trial steps find no first step above dt_min, so the run starts at
  // dt_min (5 ms) and fails in its third step, after t = 0.01 s: the bag holds the samples before the failure,
  // t = 0 and 0.01 s (runner: the same two rows).
  const TempDir dir("flexmbd_node_exit");
  const std::string bag = dir.File("failing.bag");
  NodeProcess node("flexmbd_failing", {"_bag:=" + bag});
  EXPECT_EQ(node.WaitForExit(kTimeout), std::optional<int>(kRunFailedExit));
  EXPECT_TRUE(Contains(node.Output(), "run failed: step size fell below dt_min")) << node.Output();
  const Samples recorded = ReadBagSamples(bag, "flexmbd_failing");
  ASSERT_EQ(recorded.joint_states.size(), 2u);
  EXPECT_NEAR(TimeOf(recorded.joint_states[1]), kSamplePeriod, kStampResolution);
}

long FatalLines(const std::string& output) {
  long count = 0;
  for (size_t at = output.find("[FATAL]"); at != std::string::npos; at = output.find("[FATAL]", at + 1)) ++count;
  return count;
}

TEST(NodeExit, BagOnAFullDeviceExitsWithThreeInOneLine) {
  NodeProcess node("flexmbd_bag_full", {"_bag:=/dev/full"});
  EXPECT_EQ(node.WaitForExit(kTimeout), std::optional<int>(kRunFailedExit)) << node.Output();
  EXPECT_EQ(FatalLines(node.Output()), 1) << node.Output();
  EXPECT_TRUE(Contains(node.Output(), "flexmbd: bag '/dev/full': writing failed after 0 samples (")) << node.Output();
}

TEST(NodeExit, BagOnADiskFillingUpMidRunExitsWithThreeInOneLine) {
  // The 201 samples of short_double_pendulum.yaml make a bag of about 120 kB; a 60 kB cap on the node's files
  // (RLIMIT_FSIZE, inherited by the node only) fails a write in the node's writer thread, which passes the
  // error to the run loop.
  const TempDir dir("flexmbd_node_exit");
  std::unique_ptr<NodeProcess> node;
  {
    const FileSizeLimit cap(60000);
    node = std::make_unique<NodeProcess>("flexmbd_bag_capped",
                                         std::vector<std::string>{"_bag:=" + dir.File("capped.bag")});
  }
  EXPECT_EQ(node->WaitForExit(kTimeout), std::optional<int>(kRunFailedExit)) << node->Output();
  EXPECT_EQ(FatalLines(node->Output()), 1) << node->Output();
  EXPECT_TRUE(Contains(node->Output(), "flexmbd: bag '" + dir.File("capped.bag") + "': writing failed after "))
      << node->Output();
  EXPECT_TRUE(Contains(node->Output(), "File too large")) << node->Output();
}

TEST(NodeExit, CsvWriteFailureInTheWriterThreadExitsWithThreeInOneLine) {
  // output.csv = /dev/full: the CSV's first 64 KiB go out from the writer thread, about 150 rows into the
  // 201-sample run.
  NodeProcess node("flexmbd_csv_full", {});
  EXPECT_EQ(node.WaitForExit(kTimeout), std::optional<int>(kRunFailedExit)) << node.Output();
  EXPECT_EQ(FatalLines(node.Output()), 1) << node.Output();
  EXPECT_TRUE(Contains(node.Output(), "flexmbd: output.csv: writing '/dev/full' failed (No space left on device); "
                                      "the file holds nothing"))
      << node.Output();
}

}  // namespace node_exit_test
}  // namespace test
}  // namespace flexmbd
