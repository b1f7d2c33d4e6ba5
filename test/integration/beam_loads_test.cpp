// ~beam_loads on the beam arm of test/data (test/data/urdf/beam_arm.urdf: a 1 m beam clamped along the world
// x axis carrying a 2 kg tip body) made stiff and started at its static equilibrium under gravity by
// test/integration/data/beam_arm_stations.yaml, with stations at s = 0, 0.5 and 1 m, run to 0.5 s at 100
// samples/s. One run serves every test: the node records its bag, the recorder the topics, the runner its CSV.

#include <gtest/gtest.h>

#include <cmath>

#include "helpers/beam_loads_csv.hpp"
#include "helpers/csv_table.hpp"
#include "helpers/recorded_run_suite.hpp"

namespace flexmbd {
namespace test {
namespace beam_loads_test {

constexpr char kNodeName[] = "flexmbd_beam_loads";
constexpr char kUrdf[] = "test/data/urdf/beam_arm.urdf";
constexpr char kConfig[] = "test/integration/data/beam_arm_stations.yaml";
constexpr double kEndTime = 0.5;
constexpr size_t kSampleCount = 51;  // t = 0, 0.01, ..., 0.5 s
// The stations of the YAML, in its order.
const std::vector<double> kStations{0.0, 0.5, 1.0};
// The arm: beam mass per length and length (YAML), tip mass (URDF), gravity along -z.
constexpr double kBeamMassPerLength = 2.5, kLength = 1.0, kTipMass = 2.0, kG = 9.81;
// Same run, same steps: the node's records equal the runner's CSV to its 17 digits.
constexpr double kSameRunTolerance = 1.0e-9;

class BeamLoads : public RecordedRunSuite<BeamLoads> {
 public:
  static constexpr char kAwaited[] = "~beam_loads";
  static NodeRunCase Case() {
    return {kNodeName, kUrdf, kConfig, /*record_bag=*/true, ReachesEnd(&Samples::beam_loads, kEndTime)};
  }
};

TEST_F(BeamLoads, MessagesNameTheConfiguredStations) {
  // Reference: output.beam_stations.arm of the YAML: station k at kStations[k], every sample.
  const std::vector<BeamLoadsArray>& messages = record_->topics.beam_loads;
  ASSERT_EQ(messages.size(), kSampleCount);
  for (const BeamLoadsArray& message : messages) {
    ASSERT_EQ(message.stations.size(), kStations.size());
    for (size_t k = 0; k < kStations.size(); ++k) {
      EXPECT_EQ(message.stations[k].beam, "arm");
      EXPECT_EQ(message.stations[k].station, static_cast<int>(k));
      EXPECT_EQ(message.stations[k].s, kStations[k]);
    }
  }
}

TEST_F(BeamLoads, RecordsMatchTheRunnersCsv) {
  ASSERT_EQ(record_->csv.rows.size(), kSampleCount) << "the runner did not write its CSV";
  ExpectBeamLoadsMatchCsv(record_->topics.beam_loads, record_->csv, kSameRunTolerance);
}

TEST_F(BeamLoads, NodesBagHoldsWhatWasPublished) {
  // Reference: the messages received; the bag keeps float64 and the header as published.
  const std::vector<BeamLoadsArray>& bag = record_->bag.beam_loads;
  ASSERT_EQ(bag.size(), record_->topics.beam_loads.size());
  for (size_t k = 0; k < bag.size(); ++k) EXPECT_EQ(bag[k], record_->topics.beam_loads[k]) << "sample " << k;
}

TEST_F(BeamLoads, BendingMomentsCarryTheWeightBeyondEachStation) {
  // At rest a section carries the weight beyond it: about section axis 2 (= world y, the beam lies along x) the
  // part beyond s exerts M2(s) = g (m (L - s)^2 / 2 + m_tip (L - s)), g (m L^2 / 2 + m_tip L) = 31.88 N m at the
  // root. The lever arms are those of the undeformed arm to within its shortening, at most theta_tip^2 L / 2 =
  // 1e-4 L (theta_tip = 0.014 rad); the lumped weights have the exact moment about the root and the 2 cubic
  // elements give the quartic moment curve of the uniform weight to 1e-4 of the root moment (measured 5e-5 at
  // the root, 9e-5 at s = L/2): 5e-4 of the root moment bounds both. Bending about axis 3 (M3) has no load.
  const double root_moment = kG * (kBeamMassPerLength * kLength * kLength / 2 + kTipMass * kLength);
  constexpr double kBendingTolerance = 5.0e-4;
  for (const BeamLoadsArray& message : record_->topics.beam_loads) {
    ASSERT_EQ(message.stations.size(), kStations.size());
    for (const BeamStationLoads& station : message.stations) {
      const double arm = kLength - station.s;
      const double expected = kG * (kBeamMassPerLength * arm * arm / 2 + kTipMass * arm);
      EXPECT_NEAR(station.M2, expected, kBendingTolerance * root_moment)
          << "s = " << station.s << " m, t = " << TimeOf(message) << " s";
      EXPECT_NEAR(station.M3, 0.0, kBendingTolerance * root_moment) << "s = " << station.s << " m";
    }
  }
}

TEST_F(BeamLoads, ShearForcesCarryTheWeightBeyondEachStation) {
  // The same balance for forces: V3(s) = -g (m (L - s) + m_tip) (section axis 3 = world z, up), 44.1 N at the
  // root. The weights are lumped at the nodes, L / 6 apart (2 cubic elements): the staircase of shear they
  // make differs from the continuous line by up to half a node's weight, g m L / 12 = 2.0 N, which bounds
  // the recovered value. The axial force is the shear turned by the slope, at most 44.1 N x 0.014 = 0.6 N.
  const double node_weight_half = kG * kBeamMassPerLength * kLength / 12;
  const double axial_bound = kG * (kBeamMassPerLength * kLength + kTipMass) * 0.014;
  for (const BeamLoadsArray& message : record_->topics.beam_loads) {
    for (const BeamStationLoads& station : message.stations) {
      const double expected = -kG * (kBeamMassPerLength * (kLength - station.s) + kTipMass);
      EXPECT_NEAR(station.V3, expected, node_weight_half) << "s = " << station.s << " m, t = " << TimeOf(message);
      EXPECT_NEAR(station.N, 0.0, axial_bound) << "s = " << station.s << " m";
      EXPECT_NEAR(station.V2, 0.0, node_weight_half) << "s = " << station.s << " m";
    }
  }
}

}  // namespace beam_loads_test
}  // namespace test
}  // namespace flexmbd
