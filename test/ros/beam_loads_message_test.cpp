// FillBeamLoads (include/flexmbd/ros/message_conversions.hpp): the ~beam_loads message of a sample, from
// hand-made stations and records.

#include <gtest/gtest.h>

#include "flexmbd/ros/message_conversions.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace beam_loads_message_test {

// Hand-made stations: two on one beam (indices 0 and 1), one on another; element pointers are not read.
const std::vector<BeamStationInfo> kStations{{"arm", 0, 0.0, nullptr, 0.0},
                                             {"arm", 1, 0.75, nullptr, 0.25},
                                             {"boom", 0, 2.5, nullptr, 0.5}};

// Record k holds values that tell every field apart: load i = 100 k + i, strain i = 1e-3 (100 k + i),
// displacement i = 10 k + i + 0.5, rotation i = 0.01 (10 k + i + 1).
BeamStationSample DistinctRecord(int k) {
  BeamStationSample record;
  for (int i = 0; i < 6; ++i) {
    record.load[i] = 100.0 * k + i;
    record.strain[i] = 1.0e-3 * (100.0 * k + i);
  }
  for (int i = 0; i < 3; ++i) {
    record.displacement[i] = 10.0 * k + i + 0.5;
    record.rotation[i] = 0.01 * (10.0 * k + i + 1.0);
  }
  return record;
}

OutputSample SampleWithStations(int count, int first_record) {
  OutputSample sample;
  sample.t = 0.75;
  for (int k = 0; k < count; ++k) sample.beam_stations.push_back(DistinctRecord(first_record + k));
  return sample;
}

TEST(BeamLoadsMessage, NamesEveryStationAndCopiesItsRecord) {
  // Reference: the hand-made records above, entry k from station k; loads and strains in the order of
  // BeamStationSample (N, V2, V3, T, M2, M3; e1, g2, g3, k1, k2, k3).
  BeamLoadsArray msg;
  FillBeamLoads(kStations, SampleWithStations(3, 0), &msg);
  ASSERT_EQ(msg.stations.size(), 3u);
  const BeamStationLoads& second = msg.stations[1];
  EXPECT_EQ(second.beam, "arm");
  EXPECT_EQ(second.station, 1);
  EXPECT_EQ(second.s, 0.75);
  EXPECT_EQ(second.N, 100.0);
  EXPECT_EQ(second.V2, 101.0);
  EXPECT_EQ(second.V3, 102.0);
  EXPECT_EQ(second.T, 103.0);
  EXPECT_EQ(second.M2, 104.0);
  EXPECT_EQ(second.M3, 105.0);
  EXPECT_EQ(second.e1, 1.0e-3 * 100.0);
  EXPECT_EQ(second.g2, 1.0e-3 * 101.0);
  EXPECT_EQ(second.g3, 1.0e-3 * 102.0);
  EXPECT_EQ(second.k1, 1.0e-3 * 103.0);
  EXPECT_EQ(second.k2, 1.0e-3 * 104.0);
  EXPECT_EQ(second.k3, 1.0e-3 * 105.0);
  EXPECT_EQ(second.displacement.x, 10.5);
  EXPECT_EQ(second.displacement.y, 11.5);
  EXPECT_EQ(second.displacement.z, 12.5);
  EXPECT_EQ(second.rotation.x, 0.01 * 11.0);
  EXPECT_EQ(second.rotation.y, 0.01 * 12.0);
  EXPECT_EQ(second.rotation.z, 0.01 * 13.0);
  const BeamStationLoads& boom = msg.stations[2];
  EXPECT_EQ(boom.beam, "boom");
  EXPECT_EQ(boom.station, 0);
  EXPECT_EQ(boom.s, 2.5);
  EXPECT_EQ(boom.N, 200.0);
  EXPECT_EQ(msg.stations[0].M3, 5.0);
}

TEST(BeamLoadsMessage, RefilledMessageHoldsOnlyTheNewSample) {
  // A recycled message is filled again: it must not keep entries or values of the sample it held.
  BeamLoadsArray msg;
  FillBeamLoads(kStations, SampleWithStations(3, 0), &msg);
  const std::vector<BeamStationInfo> one_station{{"mast", 4, 1.5, nullptr, 0.0}};
  FillBeamLoads(one_station, SampleWithStations(1, 7), &msg);
  ASSERT_EQ(msg.stations.size(), 1u);
  EXPECT_EQ(msg.stations[0].beam, "mast");
  EXPECT_EQ(msg.stations[0].station, 4);
  EXPECT_EQ(msg.stations[0].s, 1.5);
  EXPECT_EQ(msg.stations[0].V2, 701.0);
  EXPECT_EQ(msg.stations[0].rotation.z, 0.01 * 73.0);
}

TEST(BeamLoadsMessage, ModelWithoutStationsGivesNoBeamLoads) {
  // test/data beam_arm has a beam but no output.beam_stations.
  const Model model = test::BeamArm();
  ASSERT_TRUE(model.beam_stations().empty());
  BeamLoadsArray msg;
  FillBeamLoads(model.beam_stations(), SampleWithStations(0, 0), &msg);
  EXPECT_TRUE(msg.stations.empty());
}

}  // namespace beam_loads_message_test
}  // namespace ros
}  // namespace flexmbd
