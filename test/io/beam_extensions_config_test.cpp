// Beam damping, section offsets, distributed loads and station outputs from YAML (src/io/yaml_beams.cpp,
// yaml_loads.cpp, yaml_beam_stations.cpp; docs/config.md). Reference: the values written below.

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace beam_extensions_config_test {
using test::ConfigErrorOf;
using test::LoadDataUrdf;

const char kArmYaml[] = R"(
beams:
  arm:
    length: 1.0
    elements: 2
    damping: 0.002
    section: {EA: 1.0e7, GA2: 4.0e6, GA3: 4.0e6, GJ: 50.0, EI2: 80.0, EI3: 100.0, m: 2.5, m_ii: [0.002, 0.001, 0.001],
              offsets: {cg: [0.01, -0.02], shear_center: [0.03, 0.04]}}
output: {beam_stations: {arm: [0.0, 0.25, 1.0]}}
loads:
  - {body: arm, force: [0.0, 0.0, -2.0], distributed: true, frame: body}
)";

std::string Replaced(const std::string& from, const std::string& to) {
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find(from), from.size(), to);
  return yaml;
}

// Loading `yaml` fails with a message that contains `expected`.
void ExpectError(const std::string& yaml, const std::string& expected) {
  EXPECT_CONFIG_ERROR(LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml"), expected);
}

TEST(BeamExtensionsConfig, DampingOffsetsLoadsAndStationsAreRead) {
  const ModelSpec spec = LoadDataUrdf("beam_arm.urdf", kArmYaml, "arm.yaml");
  const BeamSpec& beam = spec.beams[0];
  EXPECT_EQ(beam.damping, 0.002);
  EXPECT_EQ(beam.section.cg_offset, Eigen::Vector2d(0.01, -0.02));
  EXPECT_EQ(beam.section.shear_center_offset, Eigen::Vector2d(0.03, 0.04));
  ASSERT_EQ(spec.loads.size(), 1u);
  EXPECT_TRUE(spec.loads[0].distributed);
  EXPECT_EQ(spec.loads[0].frame, LoadSpec::Frame::kBody);
  EXPECT_EQ(spec.output.beam_stations.at("arm"), (std::vector<double>{0.0, 0.25, 1.0}));
  // The model samples them on their elements: 0.25 m lies in the first of two 0.5 m elements.
  const Model model = BuildModel(spec);
  ASSERT_EQ(model.beam_stations().size(), 3u);
  EXPECT_EQ(model.beam_stations()[1].element, model.beams()[0].elements[0]);
  EXPECT_DOUBLE_EQ(model.beam_stations()[1].s_element, 0.25);
  EXPECT_EQ(model.beam_stations()[2].element, model.beams()[0].elements[1]);
}

TEST(BeamExtensionsConfig, NegativeDampingNamesTheField) {
  ExpectError(Replaced("damping: 0.002", "damping: -0.1"),
              "arm.yaml: beams.arm.damping: -0.1 is negative; expected a damping time mu >= 0 [s]");
}

TEST(BeamExtensionsConfig, StationBeyondTheTipNamesTheEntry) {
  ExpectError(Replaced("[0.0, 0.25, 1.0]", "[0.0, 1.5]"),
              "arm.yaml: output.beam_stations.arm[1]: 1.5 is beyond the tip; expected 0 <= s <= 1 [m]");
}

TEST(BeamExtensionsConfig, NegativeStationNamesTheEntry) {
  ExpectError(Replaced("[0.0, 0.25, 1.0]", "[-0.5]"),
              "arm.yaml: output.beam_stations.arm[0]: -0.5 is negative; expected a distance from the root");
}

TEST(BeamExtensionsConfig, StationsOnUnknownBeamListTheBeams) {
  ExpectError(Replaced("{arm: [0.0, 0.25, 1.0]}", "{boom: [0.5]}"),
              "arm.yaml: output.beam_stations.boom: no beam 'boom' in beam_arm.urdf; beams are: arm");
}

TEST(BeamExtensionsConfig, MalformedCentreOfMassOffsetNamesTheField) {
  ExpectError(Replaced("cg: [0.01, -0.02]", "cg: [0.01, -0.02, 0.0]"),
              "arm.yaml: beams.arm.section.offsets.cg: 3 numbers; expected [y, z], the offset in the "
              "section frame [m]");
}

TEST(BeamExtensionsConfig, UnknownOffsetKeyIsRejected) {
  ExpectError(Replaced("shear_center:", "shear_centre:"),
              "arm.yaml: beams.arm.section.offsets.shear_centre: unknown key");
}

TEST(BeamExtensionsConfig, DistributedLoadOnARigidBodyIsRejected) {
  ExpectError(Replaced("body: arm,", "body: tip,"),
              "arm.yaml: loads[0].distributed: true on 'tip', which is not a beam; expected a link under beams:");
}

TEST(BeamExtensionsConfig, DistributedLoadWithAPointIsRejected) {
  ExpectError(Replaced("distributed: true,", "distributed: true, point: [0.5, 0, 0],"),
              "arm.yaml: loads[0].point: is given for a distributed load; expected no point");
}

TEST(BeamExtensionsConfig, MomentOnABeamActsOnTheNodeItsPointPicks) {
  // Found as a user: a cantilever's tip moment could not be given (a moment's point was refused), and without a
  // point the moment went to the clamped root node, where it moved nothing.
  const ModelSpec spec =
      LoadDataUrdf("beam_arm.urdf", Replaced("force: [0.0, 0.0, -2.0], distributed: true, frame: body",
                                             "moment: [0.0, 0.0, 3.0], point: [1.0, 0.0, 0.0]"),
                   "arm.yaml");
  ASSERT_EQ(spec.loads.size(), 1u);
  EXPECT_EQ(spec.loads[0].kind, LoadSpec::Kind::kMoment);
  EXPECT_EQ(spec.loads[0].p_BoP_B, Vec3(1.0, 0.0, 0.0));
}

TEST(BeamExtensionsConfig, MomentOffTheBeamAxisOrOnARigidBodyWithAPointIsRejected) {
  ExpectError(Replaced("force: [0.0, 0.0, -2.0], distributed: true, frame: body",
                       "moment: [0.0, 0.0, 3.0], point: [1.0, 0.1, 0.0]"),
              "arm.yaml: loads[0].point: [1, 0.1, 0] is off the axis of beam 'arm'; expected [x, 0, 0] for a "
              "moment: x picks the node it acts on, and a moment has no lever arm");
  ExpectError(Replaced("{body: arm, force: [0.0, 0.0, -2.0], distributed: true, frame: body}",
                       "{body: tip, moment: [0.0, 0.0, 3.0], point: [0.1, 0.0, 0.0]}"),
              "arm.yaml: loads[0].point: applies only to forces, and to moments on beams (where its x picks the "
              "node); a moment on the rigid body 'tip' has no point of application");
}

TEST(BeamExtensionsConfig, StationsOffTheBeamAreRejectedAtModelBuild) {
  // Hand-written specs skip the YAML checks; the model build repeats them.
  ModelSpec spec = LoadDataUrdf("beam_arm.urdf", kArmYaml, "arm.yaml");
  spec.output.beam_stations["arm"] = {2.0};
  const std::string message = ConfigErrorOf([&] { BuildModel(spec); });
  EXPECT_NE(message.find("output.beam_stations.arm[0]: 2 is off the beam; expected 0 <= s <= 1 [m]"),
            std::string::npos)
      << message;
}

}  // namespace beam_extensions_config_test
}  // namespace flexmbd
