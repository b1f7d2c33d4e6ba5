// BagSink (include/flexmbd/ros/bag_sink.hpp) on a model with strip stations and no aero sections: ~aero_loads
// is recorded for every sample, its strip stations named and valued as the samples' (OutputSample::strip_stations).

#include <gtest/gtest.h>

#include "default_bag.hpp"
#include "recorded_bag.hpp"

namespace flexmbd {
namespace ros {
namespace bag_strip_stations_test {

constexpr char kWingUrdf[] = "config/goland_wing/goland_wing.urdf";

TEST(BagStripStations, HoldsTheStripLoadsOfEverySample) {
  // Reference: the samples of the first 5 ms of a dynamic run of the twisting wing (test/data), every step;
  // float64 fields and the bag's serialisation are exact.
  const std::string path = testing::TempDir() + "bag_strip_stations.bag";
  ModelSpec spec =
      LoadModelSpec(test::SourcePath(kWingUrdf), test::SourcePath("test/data/yaml/wing_twist_strips.yaml"));
  spec.solver.analysis = SolverSpec::Analysis::kDynamic;
  spec.solver.t_end = 5.0e-3;
  spec.output.rate_hz = 0.0;
  const Model model = BuildModel(spec);
  ASSERT_TRUE(model.aero_sections().empty());
  const std::vector<OutputSample> samples = test::RecordRunToBag(model, kWingUrdf, path).samples;
  const test::Samples bag = test::ReadDefaultBag(path);
  ASSERT_GT(samples.size(), 2u);
  ASSERT_EQ(bag.aero_loads.size(), samples.size());
  const std::vector<double>& stations = spec.output.strip_stations.at("wing");
  for (size_t k = 0; k < samples.size(); ++k) {
    const AeroLoadsArray& message = bag.aero_loads[k];
    EXPECT_TRUE(message.sections.empty());
    ASSERT_EQ(message.strip_stations.size(), stations.size());
    for (size_t i = 0; i < stations.size(); ++i) {
      const AeroStripStationLoads& entry = message.strip_stations[i];
      const AeroSectionSample& value = samples[k].strip_stations[i];
      EXPECT_EQ(entry.strip, "wing");
      EXPECT_EQ(entry.station, i);
      EXPECT_EQ(entry.s, stations[i]);
      EXPECT_EQ(entry.lift, value.lift) << "sample " << k << ", station " << i;
      EXPECT_EQ(entry.moment, value.moment);
      EXPECT_EQ(entry.hinge_moment, value.hinge_moment);
      ASSERT_EQ(entry.inflow.size(), 4u);
      for (int j = 0; j < 4; ++j) EXPECT_EQ(entry.inflow[j], value.inflow[j]);
    }
  }
  // The stream lifts the wing from the start: Wagner's lift begins at half the steady 3.1 N/m (pi rho b V^2
  // 2 alpha0) and grows over b / V = 25 ms.
  EXPECT_GT(bag.aero_loads.back().strip_stations[0].lift, 1.5);
}

}  // namespace bag_strip_stations_test
}  // namespace ros
}  // namespace flexmbd
