// ~aero_loads on the Conner typical section (config/conner_section/conner_section.urdf) resting in a steady
// 22 m/s stream at its static aeroelastic equilibrium (test/integration/data/conner_steady.yaml: the pitch spring
// rests at 3 deg, static_first), run to 0.5 s at 100 samples/s. One run serves every test: the node records its
// bag, the recorder the topics, the runner its CSV.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "helpers/aero_loads_csv.hpp"
#include "helpers/recorded_run_suite.hpp"

namespace flexmbd {
namespace test {
namespace aero_loads_test {

constexpr char kNodeName[] = "flexmbd_aero_loads";
constexpr char kUrdf[] = "config/conner_section/conner_section.urdf";
constexpr char kConfig[] = "test/integration/data/conner_steady.yaml";
constexpr double kEndTime = 0.5;
constexpr size_t kSampleCount = 51;  // t = 0, 0.01, ..., 0.5 s
constexpr int kInflowStates = 6;     // aero.sections.conner.inflow_states
// Same run, same steps: the node's records equal the runner's CSV to its 17 digits.
constexpr double kSameRunTolerance = 1.0e-9;

class AeroLoads : public RecordedRunSuite<AeroLoads> {
 public:
  static constexpr char kAwaited[] = "~aero_loads";
  static NodeRunCase Case() {
    return {kNodeName, kUrdf, kConfig, /*record_bag=*/true, ReachesEnd(&Samples::aero_loads, kEndTime)};
  }
};

TEST_F(AeroLoads, MessagesNameTheSectionAndItsInflowStates) {
  // Reference: aero.sections of the YAML: one section, conner, with 6 inflow states, in every sample.
  const std::vector<AeroLoadsArray>& messages = record_->topics.aero_loads;
  ASSERT_EQ(messages.size(), kSampleCount);
  for (const AeroLoadsArray& message : messages) {
    ASSERT_EQ(message.sections.size(), 1u);
    EXPECT_EQ(message.sections[0].section, "conner");
    EXPECT_EQ(message.sections[0].inflow.size(), static_cast<size_t>(kInflowStates));
  }
}

TEST_F(AeroLoads, RecordsMatchTheRunnersCsv) {
  // Reference: the aero.<section>.* columns the runner writes for the same case.
  ASSERT_EQ(record_->csv.rows.size(), kSampleCount) << "the runner did not write its CSV";
  ExpectAeroLoadsMatchCsv(record_->topics.aero_loads, record_->csv, kSameRunTolerance);
}

TEST_F(AeroLoads, NodesBagHoldsWhatWasPublished) {
  // Reference: the messages received; the bag keeps float64 and the header as published.
  const std::vector<AeroLoadsArray>& bag = record_->bag.aero_loads;
  ASSERT_EQ(bag.size(), record_->topics.aero_loads.size());
  for (size_t k = 0; k < bag.size(); ++k) EXPECT_EQ(bag[k], record_->topics.aero_loads[k]) << "sample " << k;
}

TEST_F(AeroLoads, SteadyLoadsHoldTheSpringsAtTheThinAirfoilValue) {
  // At the static aeroelastic equilibrium the flow is steady: the inflow states are zero and the lift is the
  // steady thin-airfoil lift 2 pi q (2b) span (alpha + T10 delta / pi), T10 = sqrt(1 - c^2) + acos(c)
  // (Theodorsen's flap term), with alpha and delta the sample's pitch and flap (joint_states, same message
  // order). Each load holds its spring: lift K_h h, moment K_alpha (alpha - 3 deg), hinge moment K_beta delta.
  // The lift is evaluated at the sample's own alpha and delta, so the closed form holds to the flap series' cut
  // (6e-8 relative, docs/theory.md (A4)); the balances hold to the static solve's Newton tolerance (1e-6
  // relative) while the run stays at rest, its steps only adding round-off.
  constexpr double kRelative = 1.0e-6;
  constexpr double kRho = 1.225, kU = 22.0, kB = 0.127, kC = 0.5;
  constexpr double kPlungeStiffness = 2818.8, kPitchStiffness = 37.34, kFlapStiffness = 3.9;
  const double t10 = std::sqrt(1 - kC * kC) + std::acos(kC);
  const std::vector<AeroLoadsArray>& messages = record_->topics.aero_loads;
  const std::vector<sensor_msgs::JointState>& states = record_->topics.joint_states;
  ASSERT_EQ(states.size(), messages.size());
  for (size_t k = 0; k < messages.size(); ++k) {
    ASSERT_EQ(states[k].name, (std::vector<std::string>{"plunge", "pitch", "flap_hinge"}));
    const double plunge = states[k].position[0], alpha = states[k].position[1], delta = states[k].position[2];
    const AeroSectionLoads& section = messages[k].sections.at(0);
    const double lift = 2 * M_PI * 0.5 * kRho * kU * kU * 2 * kB * (alpha + t10 / M_PI * delta);
    ASSERT_GT(alpha, 0.01) << "the section should rest at a positive pitch, t = " << TimeOf(messages[k]);
    EXPECT_NEAR(section.lift, lift, kRelative * lift) << "t = " << TimeOf(messages[k]);
    EXPECT_NEAR(section.lift, kPlungeStiffness * plunge, kRelative * lift) << "t = " << TimeOf(messages[k]);
    EXPECT_NEAR(section.moment, kPitchStiffness * (alpha - 3.0 * M_PI / 180), kRelative * std::abs(section.moment));
    EXPECT_NEAR(section.hinge_moment, kFlapStiffness * delta, kRelative * std::abs(section.hinge_moment));
    // mu_k are velocities of the wake's induced flow; steady, they stay at the round-off of U (22 m/s)
    for (double mu : section.inflow) EXPECT_NEAR(mu, 0.0, kRelative * kU) << "t = " << TimeOf(messages[k]);
  }
}

}  // namespace aero_loads_test
}  // namespace test
}  // namespace flexmbd
