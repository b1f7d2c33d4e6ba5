// flexmbd_run --bag: the runner writes the node's bag without roscore, and it holds the same samples as the
// runner's CSV (lossless: the CSV prints 17 significant digits, the bag keeps float64). A write that fails
// (a full disk: /dev/full, or a file size cap) ends the run with exit 3 and one line, never an abort.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "../integration/helpers/file_size_limit.hpp"

#include "../integration/helpers/beam_loads_csv.hpp"
#include "../integration/helpers/csv_table.hpp"
#include "default_bag.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace runner_bag_test {

constexpr int kBadInputExit = 2;
constexpr int kRunFailedExit = 3;
// ros::Time keeps nanoseconds.
constexpr double kStampResolution = 1.0e-9;
constexpr char kUrdf[] = "config/double_pendulum/double_pendulum.urdf";
constexpr char kConfig[] = "config/double_pendulum/double_pendulum.yaml";

TEST(RunnerBag, HoldsTheSamplesOfTheCsv) {
  const std::string bag_path = testing::TempDir() + "runner.bag";
  const std::string csv_path = testing::TempDir() + "runner.csv";
  ASSERT_EQ(test::RunRunner(kUrdf, kConfig, "--bag " + bag_path + " --csv " + csv_path), 0);
  const test::CsvTable csv = test::ReadCsv(csv_path);
  const test::Samples bag = test::ReadDefaultBag(bag_path);
  ASSERT_EQ(bag.joint_states.size(), csv.rows.size());
  ASSERT_EQ(bag.energy.size(), csv.rows.size());
  ASSERT_EQ(bag.reactions.size(), csv.rows.size());
  ASSERT_EQ(bag.solver.size(), csv.rows.size());
  for (size_t k = 0; k < csv.rows.size(); ++k) {
    const std::vector<double>& row = csv.rows[k];
    const sensor_msgs::JointState& joints = bag.joint_states[k];
    EXPECT_NEAR(test::TimeOf(joints), row[csv.Column("t")], kStampResolution);
    for (size_t v = 0; v < joints.name.size(); ++v) {
      const std::string prefix = "joint." + joints.name[v];
      EXPECT_EQ(joints.position[v], row[csv.Column(prefix + ".position")]) << "row " << k;
      EXPECT_EQ(joints.velocity[v], row[csv.Column(prefix + ".velocity")]) << "row " << k;
      EXPECT_EQ(joints.effort[v], row[csv.Column(prefix + ".effort")]) << "row " << k;
    }
    for (const JointReaction& reaction : bag.reactions[k].joints) {
      const std::string prefix = "joint." + reaction.joint;
      EXPECT_EQ(reaction.force.z, row[csv.Column(prefix + ".reaction_force_z")]) << "row " << k;
      EXPECT_EQ(reaction.moment.y, row[csv.Column(prefix + ".reaction_moment_y")]) << "row " << k;
    }
    EXPECT_EQ(bag.energy[k].kinetic, row[csv.Column("energy.kinetic")]) << "row " << k;
    EXPECT_EQ(bag.energy[k].potential, row[csv.Column("energy.potential")]) << "row " << k;
    EXPECT_EQ(bag.energy[k].external_work, row[csv.Column("energy.external_work")]) << "row " << k;
    EXPECT_EQ(bag.energy[k].dissipated, row[csv.Column("energy.dissipated")]) << "row " << k;
    EXPECT_EQ(bag.energy[k].numerical_dissipation, row[csv.Column("energy.numerical_dissipation")]) << "row " << k;
    EXPECT_EQ(bag.solver[k].dt, row[csv.Column("solver.dt")]) << "row " << k;
    EXPECT_EQ(bag.solver[k].iterations, row[csv.Column("solver.iterations")]) << "row " << k;
  }
}

TEST(RunnerBag, HoldsTheBeamLoadsOfTheCsv) {
  // The beam arm with stations of the ~beam_loads rostest: the bag and the CSV of one run, so exactly equal.
  const std::string bag_path = testing::TempDir() + "runner_beam.bag";
  const std::string csv_path = testing::TempDir() + "runner_beam.csv";
  ASSERT_EQ(test::RunRunner("test/data/urdf/beam_arm.urdf", "test/integration/data/beam_arm_stations.yaml",
                            "--bag " + bag_path + " --csv " + csv_path),
            0);
  const test::Samples bag = test::ReadDefaultBag(bag_path);
  test::ExpectBeamLoadsMatchCsv(bag.beam_loads, test::ReadCsv(csv_path), 0.0);
}

TEST(RunnerBag, UnwritableBagPathExitsWithTwo) {
  EXPECT_EQ(test::RunRunner(kUrdf, kConfig, "--bag /nonexistent_dir/run.bag"), kBadInputExit);
}

long LineCount(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(RunnerBag, BagOnAFullDeviceExitsWithThreeInOneLine) {
  std::string errors;
  EXPECT_EQ(test::RunRunner(kUrdf, kConfig, "--bag /dev/full", &errors), kRunFailedExit);
  EXPECT_EQ(LineCount(errors), 1) << errors;
  EXPECT_EQ(errors.find("flexmbd_run: bag '/dev/full': writing failed after 0 samples ("), 0u) << errors;
  EXPECT_NE(errors.find("No space left on device); the bag holds no sample"), std::string::npos) << errors;
}

TEST(RunnerBag, CsvOnAFullDeviceLeavesAClosedBagOfTheSamplesBefore) {
  // The CSV fails when its first 64 KiB go out, about 100 rows in: the bag is then closed (indexed, readable)
  // holding every sample up to the failure, t = 0, 0.01, ... s without a gap.
  const std::string bag_path = testing::TempDir() + "runner_csv_full.bag";
  std::string errors;
  EXPECT_EQ(test::RunRunner(kUrdf, kConfig, "--bag " + bag_path + " --csv /dev/full", &errors), kRunFailedExit);
  EXPECT_EQ(LineCount(errors), 1) << errors;
  EXPECT_EQ(errors.find("flexmbd_run: output.csv: writing '/dev/full' failed (No space left on device)"), 0u)
      << errors;
  const test::Samples bag = test::ReadDefaultBag(bag_path);
  ASSERT_GE(bag.joint_states.size(), 2u);
  EXPECT_LT(bag.joint_states.size(), 1001u);  // the run was cut short
  for (size_t k = 0; k < bag.joint_states.size(); ++k) {
    EXPECT_NEAR(test::TimeOf(bag.joint_states[k]), 0.01 * k, kStampResolution) << "sample " << k;
  }
}

TEST(RunnerBag, BagOnADiskFillingUpMidRunReindexesToTheSamplesOfItsCompleteChunks) {
  // test/integration/data/dense_double_pendulum.yaml writes a 2.4 MB bag and a 1.6 MB CSV; a 2 MB cap on the
  // runner's files (RLIMIT_FSIZE, inherited) stops the bag in its third chunk. The CSV is closed complete up
  // to the failure; `rosbag reindex` recovers the bag's first two chunks, the CSV's first rows exactly.
  const std::string bag_path = testing::TempDir() + "runner_capped.bag";
  const std::string csv_path = testing::TempDir() + "runner_capped.csv";
  std::remove((testing::TempDir() + "runner_capped.orig.bag").c_str());  // reindex keeps the original here
  std::string errors;
  int status = -1;
  {
    const test::FileSizeLimit cap(2000000);
    status = test::RunRunner(kUrdf, "test/integration/data/dense_double_pendulum.yaml",
                             "--bag " + bag_path + " --csv " + csv_path, &errors);
  }
  EXPECT_EQ(status, kRunFailedExit);
  EXPECT_EQ(LineCount(errors), 1) << errors;
  EXPECT_EQ(errors.find("flexmbd_run: bag '" + bag_path + "': writing failed after "), 0u) << errors;
  EXPECT_NE(errors.find("File too large); the bag is not indexed: 'rosbag reindex " + bag_path +
                        "' recovers the samples in its complete chunks"),
            std::string::npos)
      << errors;
  ASSERT_EQ(std::system(("rosbag reindex " + bag_path + " > /dev/null").c_str()), 0);
  const test::CsvTable csv = test::ReadCsv(csv_path);
  const test::Samples bag = test::ReadDefaultBag(bag_path);
  ASSERT_GE(bag.joint_states.size(), 1000u) << "fewer samples than two chunks hold";
  ASSERT_LT(bag.joint_states.size(), csv.rows.size());
  ASSERT_LT(csv.rows.size(), 4001u);  // the run was cut short
  for (size_t k = 0; k < bag.joint_states.size(); ++k) {
    const sensor_msgs::JointState& joints = bag.joint_states[k];
    EXPECT_NEAR(test::TimeOf(joints), csv.rows[k][csv.Column("t")], kStampResolution) << "sample " << k;
    EXPECT_EQ(joints.position[1], csv.rows[k][csv.Column("joint." + joints.name[1] + ".position")]) << "sample " << k;
  }
}

}  // namespace runner_bag_test
}  // namespace ros
}  // namespace flexmbd
