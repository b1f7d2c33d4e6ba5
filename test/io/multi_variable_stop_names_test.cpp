// Stops on two variables of one joint are named by their variable (joint/k, as joint_states names it) in the CSV
// columns and the runner's contact lines: a planar joint with a lower and an upper stop on each of its two
// translations (test/data/yaml/planar_two_stops.yaml) once gave both pairs the same names.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "../verification/runner_output.hpp"
#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace multi_variable_stop_names_test {

TEST(MultiVariableStopNames, CsvColumnsAndContactLinesNameTheVariable) {
  const std::string csv_path = testing::TempDir() + "planar_two_stops.csv";
  std::string yaml = test::ReadDataText("yaml/planar_two_stops.yaml");
  const std::string output = "output: {rate_hz: 100}";
  ASSERT_NE(yaml.find(output), std::string::npos);
  yaml.replace(yaml.find(output), output.size(), "output: {rate_hz: 100, csv: " + csv_path + "}");
  const std::string out = test::RunnerOutput("test/data/urdf/planar.urdf", yaml, "planar_two_stops");
  const test::CsvTable csv = test::ReadCsv(csv_path);
  for (const std::string variable : {"plane/1", "plane/2"}) {
    for (const std::string stop : {"lower", "upper"}) {
      const std::string column = "stop." + variable + "." + stop + ".in_contact";
      EXPECT_EQ(std::count(csv.header.begin(), csv.header.end(), column), 1) << column;
      EXPECT_NE(out.find("stop " + variable + " " + stop + ": "), std::string::npos) << out;
    }
  }
}

TEST(MultiVariableStopNames, SingleVariableJointKeepsItsName) {
  const ModelSpec spec = LoadModelSpec(test::DataPath("urdf/pend_rev.urdf"), test::DataPath("yaml/stop_eigen.yaml"));
  const Model model = BuildModel(spec);
  ASSERT_EQ(model.stops().size(), 1u);
  EXPECT_EQ(model.stops()[0].joint, "pivot");
  EXPECT_EQ(model.stops()[0].stop, "upper");
}

}  // namespace multi_variable_stop_names_test
}  // namespace flexmbd
