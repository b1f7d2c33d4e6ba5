// BagSink (include/flexmbd/ros/bag_sink.hpp) on a model with beam stations: ~beam_loads is recorded for every
// sample, exactly as converted.

#include <gtest/gtest.h>

#include "default_bag.hpp"
#include "recorded_bag.hpp"

namespace flexmbd {
namespace ros {
namespace bag_beam_loads_test {

TEST(BagBeamLoads, HoldsTheBeamLoadsOfEverySample) {
  // Reference: the messages the converter made of a run of the beam arm (test/data) with two stations, sampled
  // at every step of its first 3 ms; float64 fields and the bag's serialisation are exact.
  const std::string path = testing::TempDir() + "bag_beam_loads.bag";
  ModelSpec spec = LoadModelSpec(test::SourcePath(test::kBeamArmUrdf),
                                 test::SourcePath("test/data/yaml/beam_arm.yaml"));
  spec.output.rate_hz = 0.0;
  spec.solver.t_end = 3.0e-3;
  spec.output.beam_stations["arm"] = {0.25, 1.0};
  const std::vector<SampleMessages> written =
      test::RecordRunToBag(BuildModel(spec), test::kBeamArmUrdf, path).messages;
  const test::Samples bag = test::ReadDefaultBag(path);
  ASSERT_GT(written.size(), 2u);
  ASSERT_EQ(bag.beam_loads.size(), written.size());
  ASSERT_EQ(bag.joint_states.size(), written.size());
  for (size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(bag.beam_loads[k], written[k].beam_loads) << "sample " << k;
    EXPECT_EQ(bag.beam_loads[k].header.stamp, bag.joint_states[k].header.stamp) << "sample " << k;
  }
  ASSERT_EQ(bag.beam_loads.back().stations.size(), 2u);
  EXPECT_EQ(bag.beam_loads.back().stations[1].beam, "arm");
  EXPECT_EQ(bag.beam_loads.back().stations[1].station, 1);
  EXPECT_EQ(bag.beam_loads.back().stations[1].s, 1.0);
}

}  // namespace bag_beam_loads_test
}  // namespace ros
}  // namespace flexmbd
