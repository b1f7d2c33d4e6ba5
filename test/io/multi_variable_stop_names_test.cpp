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

// The CSV header of pend_rev.urdf with its pivot made `type` and `variables` given, for 0.01 s.
std::vector<std::string> HeaderWithPivot(const std::string& type, const std::string& variables) {
  const std::string csv_path = testing::TempDir() + "pivot_" + type + ".csv";
  test::RunnerOutput("test/data/urdf/pend_rev.urdf",
                     "joints: {pivot: {type: " + type + variables + "}}\nsolver: {t_end: 0.01}\noutput: {csv: " +
                         csv_path + "}\n",
                     "pivot_" + type);
  return test::ReadCsv(csv_path).header;
}

// The columns docs/config.md lists per multi-variable joint type: joint/k per variable, in the order of
// `variables`, stops named by their variable, none for a spherical joint (which has no variable).
TEST(MultiVariableStopNames, CsvColumnsOfEachJointTypeAreThoseDocumented) {
  const auto has = [](const std::vector<std::string>& header, const std::string& column) {
    return std::count(header.begin(), header.end(), column) == 1;
  };
  const std::vector<std::string> cylindrical =
      HeaderWithPivot("cylindrical", ", variables: [{}, {backlash: {lower: -0.1, upper: 0.1}}]");
  for (const char* column : {"joint.pivot/0.position", "joint.pivot/1.velocity", "joint.pivot/1.effort",
                             "stop.pivot/1.upper.force", "joint.pivot.reaction_force_x"}) {
    EXPECT_TRUE(has(cylindrical, column)) << "cylindrical: " << column;
  }
  EXPECT_FALSE(has(cylindrical, "joint.pivot.position"));
  const std::vector<std::string> planar = HeaderWithPivot("planar", "");
  for (const char* column : {"joint.pivot/0.position", "joint.pivot/1.position", "joint.pivot/2.position"}) {
    EXPECT_TRUE(has(planar, column)) << "planar: " << column;
  }
  const std::vector<std::string> universal = HeaderWithPivot("universal", "");
  for (const char* column : {"joint.pivot/0.position", "joint.pivot/1.position"}) {
    EXPECT_TRUE(has(universal, column)) << "universal: " << column;
  }
  EXPECT_FALSE(has(universal, "joint.pivot/2.position"));
  const std::vector<std::string> spherical = HeaderWithPivot("spherical", "");
  EXPECT_TRUE(has(spherical, "joint.pivot.reaction_force_x"));
  EXPECT_EQ(std::count_if(spherical.begin(), spherical.end(),
                          [](const std::string& c) { return c.find(".position") != std::string::npos; }),
            0);
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
