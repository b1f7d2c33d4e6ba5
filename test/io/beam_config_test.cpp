// Beams from URDF + YAML (src/io/yaml_beams.cpp, urdf_reader.cpp, initial_placement.cpp). Reference: the
// values written in test/data/{urdf,yaml}/beam_arm.*.

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace beam_config_test {
using test::ConfigErrorOf;
using test::DataPath;
using test::LoadDataUrdf;

// Poses are products of a few exact numbers.
constexpr double kTolerance = 1.0e-12;

const char kArmYaml[] = R"(
beams:
  arm:
    length: 1.0
    elements: 2
    section: {EA: 1.0e7, GA2: 4.0e6, GA3: 4.0e6, GJ: 50.0, EI2: 80.0, EI3: 100.0, m: 2.5, m_ii: [0.002, 0.001, 0.001]}
)";

TEST(BeamConfig, BeamReadFromYamlAndPlacedByTheUrdf) {
  const ModelSpec spec = LoadModelSpec(DataPath("urdf/beam_arm.urdf"), DataPath("yaml/beam_arm.yaml"));
  ASSERT_EQ(spec.beams.size(), 1u);
  const BeamSpec& beam = spec.beams[0];
  EXPECT_EQ(beam.name, "arm");
  EXPECT_EQ(beam.elements, 2);
  EXPECT_EQ(beam.order, 3);
  EXPECT_EQ(beam.section.stiffness(5, 5), 100.0);
  EXPECT_EQ(beam.section.stiffness(0, 1), 0.0);
  EXPECT_EQ(beam.section.mass_per_length, 2.5);
  EXPECT_NEAR((beam.p_WB - Vec3(0, 0, 1)).norm(), 0.0, kTolerance);
  EXPECT_EQ(spec.bodies.size(), 1u);  // the tip only: the beam link is not a rigid body
}

TEST(BeamConfig, JointAtTheTipNodeBuildsAModel) {
  const Model model = BuildModel(LoadModelSpec(DataPath("urdf/beam_arm.urdf"), DataPath("yaml/beam_arm.yaml")));
  ASSERT_EQ(model.beams().size(), 1u);
  EXPECT_EQ(model.beams()[0].nodes.size(), 7u);   // 2 cubic elements
  EXPECT_EQ(model.num_nodes(), 8);                 // and the tip body (node 0: bodies come first)
  EXPECT_EQ(model.DescribeUnknown(6 * 3 + 4), "beam arm node 2 rot_y");
}

TEST(BeamConfig, JointNotOnANodeListsTheNodes) {
  const std::string urdf = test::ReadDataText("urdf/beam_arm.urdf");
  std::string moved = urdf;
  moved.replace(moved.find("xyz=\"1.0 0 0\""), 13, "xyz=\"0.4 0 0\"");
  const std::string message = ConfigErrorOf([&] {
    BuildModel(LoadModelSpecFromStrings(moved, "beam_arm.urdf", YAML::Load(kArmYaml), "arm.yaml"));
  });
  EXPECT_NE(message.find("joint 'tip_hinge': x = 0.4 m on beam 'arm' is not at a node"), std::string::npos)
      << message;
  EXPECT_NE(message.find("0.5"), std::string::npos) << message;
}

// The tip hinge of beam_arm.urdf moved to x = `x` on the 1 m beam of kArmYaml with `elements` cubic elements.
std::string TipHingeAtError(const std::string& x, int elements) {
  std::string moved = test::ReadDataText("urdf/beam_arm.urdf");
  moved.replace(moved.find("xyz=\"1.0 0 0\""), 13, "xyz=\"" + x + " 0 0\"");
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("elements: 2"), 11, "elements: " + std::to_string(elements));
  return ConfigErrorOf([&] {
    BuildModel(LoadModelSpecFromStrings(moved, "beam_arm.urdf", YAML::Load(yaml), "arm.yaml"));
  });
}

TEST(BeamConfig, JointBeforeTheRootOfALongBeamGivesTheNodeSpacing) {
  // 10 cubic elements: 31 nodes every 1/30 m, too many to list.
  EXPECT_EQ(TipHingeAtError("-0.2", 10),
            "beam_arm.urdf + arm.yaml: joint 'tip_hinge': x = -0.2 m on beam 'arm' is before its root (length 1 m, 10 "
            "element(s) of order 3: nodes 0..30 every 0.03333333333333333 m, the nearest node 0 at 0 m); expected a "
            "node position [m] k * 1 / 30 for k = 0..30");
}

TEST(BeamConfig, JointBetweenNodesNamesTheNearest) {
  EXPECT_NE(TipHingeAtError("0.52", 2).find("x = 0.52 m on beam 'arm' is not at a node (length 1 m, 2 element(s) of "
                                            "order 3: nodes 0..6 every 0.16666666666666666 m, the nearest node 3 at "
                                            "0.5 m)"),
            std::string::npos);
}

TEST(BeamConfig, NegativeSectionStiffnessNamesTheField) {
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("EI3: 100.0"), 10, "EI3: -1.0");
  const std::string message = ConfigErrorOf([&] { LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml"); });
  EXPECT_NE(message.find("arm.yaml: beams.arm.section.EI3: -1.0 is negative; expected a stiffness EI3 > 0 [N m^2]"),
            std::string::npos)
      << message;
}

TEST(BeamConfig, UnknownBeamLinkIsAFieldOfTheYamlThatNamesIt) {
  // Reference: the loader's convention for a YAML field (file: path: what); the link is missing from the URDF, which
  // the message names as where it was looked for. It once carried the URDF's name as its file.
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("arm:"), 4, "armm:");
  const std::string message = ConfigErrorOf([&] { LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml"); });
  EXPECT_EQ(message, "arm.yaml: beams.armm: no link 'armm' in beam_arm.urdf; links are: arm, tip, world; did you "
                     "mean 'arm'?");
}

TEST(BeamConfig, MassMomentsOfTheWrongLengthAreNamedAsTheSchemaNamesThem) {
  // Reference: docs/config.md, beams: m_ii = [torsional, about y, about z]; not the [x, y, z] of a vector in space.
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("m_ii: [0.002, 0.001, 0.001]"), 27, "m_ii: [0.002, 0.001]");
  const std::string message = ConfigErrorOf([&] { LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml"); });
  EXPECT_EQ(message, "arm.yaml: beams.arm.section.m_ii: [0.002, 0.001] has 2 entries; expected [torsional, about y, "
                     "about z], mass moments per length >= 0 [kg m]");
}

TEST(BeamConfig, ZeroElementsIsRejected) {
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("elements: 2"), 11, "elements: 0");
  const std::string message = ConfigErrorOf([&] { LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml"); });
  EXPECT_NE(message.find("arm.yaml: beams.arm.elements: 0"), std::string::npos) << message;
}

TEST(BeamConfig, ElementsOfNoLengthAreRejected) {
  // fuzz finding (test/fuzz): a denormal length passed the load check and its elements' length underflowed to
  // 0, failing an internal check of the beam element
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("length: 1.0"), 11, "length: 4.9e-324");
  const std::string message = ConfigErrorOf([&] { BuildModel(LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml")); });
  EXPECT_NE(message.find("beams.arm.length: 4.94066e-324 m in 2 elements gives elements of no length"),
            std::string::npos)
      << message;
}

TEST(BeamConfig, MoreElementsThanAnyRunCanHoldAreRejected) {
  // fuzz finding (test/fuzz): 1e9 elements ended in std::length_error while the nodes were laid out
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("elements: 2"), 11, "elements: 1000000000");
  const std::string message = ConfigErrorOf([&] { LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml"); });
  EXPECT_NE(message.find("arm.yaml: beams.arm.elements: 1000000000 is above 1000000"), std::string::npos) << message;
}

TEST(BeamConfig, UnknownBeamLinkListsLinks) {
  std::string yaml = kArmYaml;
  yaml.replace(yaml.find("  arm:"), 6, "  boom:");
  const std::string message = ConfigErrorOf([&] { LoadDataUrdf("beam_arm.urdf", yaml, "arm.yaml"); });
  EXPECT_NE(message.find("beams.boom"), std::string::npos) << message;
  EXPECT_NE(message.find("arm"), std::string::npos) << message;
}

TEST(BeamConfig, NotPositiveDefiniteCouplingIsRejectedAtModelBuild) {
  ModelSpec spec = LoadDataUrdf("beam_arm.urdf", kArmYaml, "arm.yaml");
  spec.beams[0].section.stiffness(0, 5) = spec.beams[0].section.stiffness(5, 0) = 1.0e6;  // |C05| > sqrt(C00 C55)
  const std::string message = ConfigErrorOf([&] { BuildModel(spec); });
  EXPECT_NE(message.find("beams.arm.section: section stiffness is not positive definite"), std::string::npos)
      << message;
}

}  // namespace beam_config_test
}  // namespace flexmbd
