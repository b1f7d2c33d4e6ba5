// ~friction on a 30 s run of the antenna with friction in its four hinges
// (test/integration/data/short_antenna_friction.yaml): every hinge slides and sticks, the sticking intervals
// and friction forces are those the runner writes for the same case, and the books of dissipated work add up.

#include <gtest/gtest.h>

#include <cmath>

#include "helpers/csv_table.hpp"
#include "helpers/recorded_run_suite.hpp"

namespace flexmbd {
namespace test {
namespace effect_friction_test {

constexpr char kNodeName[] = "flexmbd_friction";
constexpr char kUrdf[] = "config/antenna/antenna.urdf";
constexpr char kConfig[] = "test/integration/data/short_antenna_friction.yaml";
constexpr double kEndTime = 30.0;
// Same run, same steps: the node's records equal the runner's CSV to its 17 digits.
constexpr double kSameRunTolerance = 1.0e-9;
// The case: mu_k 0.15 on 0.02 m races, 50 N preload.
constexpr double kKineticBoundPerNewton = 0.15 * 0.02, kPreload = 50.0;

class EffectFriction : public RecordedRunSuite<EffectFriction> {
 public:
  static constexpr char kAwaited[] = "~friction";
  static NodeRunCase Case() {
    return {kNodeName, kUrdf, kConfig, /*record_bag=*/false, ReachesEnd(&Samples::friction, kEndTime)};
  }
};

TEST_F(EffectFriction, EveryHingeSlidesAndSticks) {
  const std::vector<JointFrictionArray>& friction = record_->topics.friction;
  ASSERT_FALSE(friction.empty());
  ASSERT_EQ(friction.front().joints.size(), 4u);
  for (size_t j = 0; j < 4; ++j) {
    EXPECT_EQ(friction.front().joints[j].joint, "B" + std::to_string(j + 1));
    int sticking = 0, sliding = 0;
    for (const JointFrictionArray& message : friction) {
      const JointFriction& f = message.joints[j];
      (f.sticking ? sticking : sliding) += 1;
      EXPECT_GE(f.normal_force, kPreload) << "radial reaction plus preload";
      if (!f.sticking && f.slip_velocity != 0) {
        // Sliding: the friction force is mu_k rho N against the slip.
        EXPECT_NEAR(std::abs(f.torque), kKineticBoundPerNewton * f.normal_force, 1e-9 * f.normal_force);
      }
    }
    EXPECT_GT(sticking, 0) << "B" << j + 1;
    EXPECT_GT(sliding, 0) << "B" << j + 1;
  }
}

TEST_F(EffectFriction, StickingIntervalsAndForcesMatchTheRunnersCsv) {
  const CsvTable& csv = record_->csv;
  const std::vector<JointFrictionArray>& friction = record_->topics.friction;
  ASSERT_EQ(csv.rows.size(), friction.size()) << "the runner did not write its CSV";
  for (size_t k = 0; k < friction.size(); ++k) {
    const std::vector<double>& row = csv.rows[k];
    for (const JointFriction& f : friction[k].joints) {
      const std::string prefix = "friction." + f.joint + ".";
      EXPECT_EQ(f.sticking, row[csv.Column(prefix + "sticking")] != 0) << prefix << " t = " << row[0];
      EXPECT_NEAR(f.torque, row[csv.Column(prefix + "torque")], kSameRunTolerance * (1 + std::abs(f.torque)));
      EXPECT_NEAR(f.work, row[csv.Column(prefix + "work")], kSameRunTolerance * (1 + f.work));
    }
  }
}

TEST_F(EffectFriction, DissipatedWorkClosesTheEnergyBooks) {
  // Spring energy at the fold: 3.5 N m/rad * ((pi/2)^2 + 3 pi^2) / 2; what the panels keep plus what friction
  // and the scheme dissipated equals it (Newton tolerance 1e-6 over ~400 steps: 1e-4 J).
  const double initial = 0.5 * 3.5 * (M_PI * M_PI / 4 + 3 * M_PI * M_PI);
  const JointFrictionArray& last = record_->topics.friction.back();
  const Energy& energy = record_->topics.energy.back();
  double friction_work = 0;
  for (const JointFriction& f : last.joints) friction_work += f.work;
  EXPECT_NEAR(energy.kinetic + energy.potential + friction_work + energy.numerical_dissipation, initial, 1e-4);
  EXPECT_NEAR(friction_work, energy.dissipated, 1e-9 * (1 + friction_work)) << "friction is the only damper";
}

}  // namespace effect_friction_test
}  // namespace test
}  // namespace flexmbd
