// ~aero_loads for strips alone: a uniform cantilever wing (config/goland_wing/goland_wing.urdf) with strips and
// strip stations but no aero sections, resting at its static aeroelastic twist in a steady stream
// (test/integration/data/wing_strips_steady.yaml), run to 0.2 s at 50 samples/s. One run serves every test: the
// node records its bag, the recorder the topics, the runner its CSV.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "helpers/aero_loads_csv.hpp"
#include "helpers/recorded_run_suite.hpp"
#include "helpers/wing_twist_closed_form.hpp"

namespace flexmbd {
namespace test {
namespace strip_loads_test {

constexpr char kNodeName[] = "flexmbd_strip_loads";
constexpr char kUrdf[] = "config/goland_wing/goland_wing.urdf";
constexpr char kConfig[] = "test/integration/data/wing_strips_steady.yaml";
constexpr double kEndTime = 0.2;
constexpr size_t kSampleCount = 11;  // t = 0, 0.02, ..., 0.2 s
constexpr int kInflowStates = 4;     // aero.strips.wing.inflow_states
// Same run, same steps: the node's records equal the runner's CSV to its 17 digits.
constexpr double kSameRunTolerance = 1.0e-9;

class StripLoads : public RecordedRunSuite<StripLoads> {
 public:
  static constexpr char kAwaited[] = "~aero_loads";
  static NodeRunCase Case() {
    return {kNodeName, kUrdf, kConfig, /*record_bag=*/true, ReachesEnd(&Samples::aero_loads, kEndTime)};
  }
};

TEST_F(StripLoads, MessagesCarryTheStripStationsAlone) {
  // Reference: output.strip_stations of the YAML: five stations along the strip wing, no aero sections.
  const WingTwistClosedForm wing;
  const std::vector<AeroLoadsArray>& messages = record_->topics.aero_loads;
  ASSERT_EQ(messages.size(), kSampleCount);
  for (const AeroLoadsArray& message : messages) {
    EXPECT_TRUE(message.sections.empty());
    ASSERT_EQ(message.strip_stations.size(), std::size(wing.kStations));
    for (size_t k = 0; k < message.strip_stations.size(); ++k) {
      const AeroStripStationLoads& station = message.strip_stations[k];
      EXPECT_EQ(station.strip, "wing");
      EXPECT_EQ(station.station, k);
      EXPECT_EQ(station.s, wing.kStations[k]);
      EXPECT_EQ(station.inflow.size(), static_cast<size_t>(kInflowStates));
    }
  }
}

TEST_F(StripLoads, RecordsMatchTheRunnersCsv) {
  // Reference: the strip.<strip>.s<k>.* columns the runner writes for the same case.
  ASSERT_EQ(record_->csv.rows.size(), kSampleCount) << "the runner did not write its CSV";
  ExpectAeroLoadsMatchCsv(record_->topics.aero_loads, record_->csv, kSameRunTolerance);
}

TEST_F(StripLoads, NodesBagHoldsWhatWasPublished) {
  // Reference: the messages received; the bag keeps float64 and the header as published.
  const std::vector<AeroLoadsArray>& bag = record_->bag.aero_loads;
  ASSERT_EQ(bag.size(), record_->topics.aero_loads.size());
  for (size_t k = 0; k < bag.size(); ++k) EXPECT_EQ(bag[k], record_->topics.aero_loads[k]) << "sample " << k;
}

TEST_F(StripLoads, SteadyLoadsFollowTheClosedFormTwist) {
  // Reference: the static aeroelastic twist of the wing (helpers/wing_twist_closed_form.hpp). The bound is that
  // of StripStations.StaticTwistOfAUniformWingMatchesTheClosedForm (test/io, where it is derived: element and
  // interpolation errors of order (lambda h)^2 / 8), 5e-4 of the root's lift; the run rests at the static
  // equilibrium, its steps adding only round-off.
  constexpr double kRelative = 5.0e-4;
  const WingTwistClosedForm wing;
  for (const AeroLoadsArray& message : record_->topics.aero_loads) {
    for (const AeroStripStationLoads& station : message.strip_stations) {
      EXPECT_NEAR(station.lift, wing.Lift(station.s), kRelative * wing.RootLift())
          << "s = " << station.s << ", t = " << TimeOf(message);
      EXPECT_NEAR(station.moment, wing.Moment(station.s), kRelative * wing.arm * wing.RootLift())
          << "s = " << station.s << ", t = " << TimeOf(message);
      EXPECT_EQ(station.hinge_moment, 0.0);  // no flap
    }
  }
}

}  // namespace strip_loads_test
}  // namespace test
}  // namespace flexmbd
