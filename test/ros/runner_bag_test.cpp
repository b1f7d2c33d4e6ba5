// flexmbd_run --bag: the runner writes the node's bag without roscore, and it holds the same samples as the
// runner's CSV (lossless: the CSV prints 17 significant digits, the bag keeps float64).

#include <gtest/gtest.h>

#include "../integration/helpers/bag_samples.hpp"
#include "../integration/helpers/beam_loads_csv.hpp"
#include "../integration/helpers/csv_table.hpp"
#include "flexmbd/ros/topic_names.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace {

constexpr int kBadInputExit = 2;
// ros::Time keeps nanoseconds.
constexpr double kStampResolution = 1.0e-9;
constexpr char kUrdf[] = "config/double_pendulum/double_pendulum.urdf";
constexpr char kConfig[] = "config/double_pendulum/double_pendulum.yaml";

TEST(RunnerBag, HoldsTheSamplesOfTheCsv) {
  const std::string bag_path = testing::TempDir() + "runner.bag";
  const std::string csv_path = testing::TempDir() + "runner.csv";
  ASSERT_EQ(test::RunRunner(kUrdf, kConfig, "--bag " + bag_path + " --csv " + csv_path), 0);
  const test::CsvTable csv = test::ReadCsv(csv_path);
  const test::Samples bag = test::ReadBagSamples(bag_path, std::string(kDefaultNodeName).substr(1));
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
    const JointReactions& reactions = bag.reactions[k];
    for (size_t j = 0; j < reactions.name.size(); ++j) {
      const std::string prefix = "joint." + reactions.name[j];
      EXPECT_EQ(reactions.force[j].z, row[csv.Column(prefix + ".reaction_force_z")]) << "row " << k;
      EXPECT_EQ(reactions.moment[j].y, row[csv.Column(prefix + ".reaction_moment_y")]) << "row " << k;
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
  const test::Samples bag = test::ReadBagSamples(bag_path, std::string(kDefaultNodeName).substr(1));
  test::ExpectBeamLoadsMatchCsv(bag.beam_loads, test::ReadCsv(csv_path), 0.0);
}

TEST(RunnerBag, UnwritableBagPathExitsWithTwo) {
  EXPECT_EQ(test::RunRunner(kUrdf, kConfig, "--bag /nonexistent_dir/run.bag"), kBadInputExit);
}

}  // namespace
}  // namespace ros
}  // namespace flexmbd
