// CSV columns of beam stations (src/io/csv_sink.cpp; docs/config.md, "output"). Reference: the column names
// documented in csv_sink.hpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/io/csv_sink.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace beam_station_csv_test {

const char kArmYaml[] = R"(
beams:
  arm:
    length: 1.0
    elements: 2
    section: {EA: 1.0e7, GA2: 4.0e6, GA3: 4.0e6, GJ: 50.0, EI2: 80.0, EI3: 100.0, m: 2.5}
output: {beam_stations: {arm: [0.25, 1.0]}}
)";

TEST(BeamStationCsv, EachStationHasEighteenNamedColumnsFilledInEveryRow) {
  const Model model = BuildModel(test::LoadDataUrdf("beam_arm.urdf", kArmYaml, "arm.yaml"));
  const std::string path = testing::TempDir() + "beam_stations.csv";
  {
    CsvSink sink(model, path);
    StepContextBuilder builder(model);
    const State& state = model.initial_state();
    sink.Write(MakeSample(model, state, builder.AtState(state), 0.0, 0));
  }
  std::ifstream in(path);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  const std::string expected =
      ",beam.arm.s1.N,beam.arm.s1.V2,beam.arm.s1.V3,beam.arm.s1.T,beam.arm.s1.M2,beam.arm.s1.M3,beam.arm.s1.e1,"
      "beam.arm.s1.g2,beam.arm.s1.g3,beam.arm.s1.k1,beam.arm.s1.k2,beam.arm.s1.k3,beam.arm.s1.ux,beam.arm.s1.uy,"
      "beam.arm.s1.uz,beam.arm.s1.rx,beam.arm.s1.ry,beam.arm.s1.rz,energy.kinetic";
  EXPECT_NE(header.find(expected), std::string::npos) << header;
  EXPECT_NE(header.find(",beam.arm.s0.N,"), std::string::npos) << header;
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), std::count(row.begin(), row.end(), ','));
}

}  // namespace beam_station_csv_test
}  // namespace flexmbd
