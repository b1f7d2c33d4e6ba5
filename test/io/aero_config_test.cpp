// `aero.sections` (src/io/yaml_aero.cpp, docs/config.md "aero.sections"): the section read from YAML with its
// defaults, and the messages of bad input, at the loader and at the model build. Reference: the values written in
// the inline documents below and config/conner_section/conner_section.urdf.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace aero_config_test {

std::string ConnerUrdf() {
  std::ifstream in(std::string(FLEXMBD_SOURCE_DIR) + "/config/conner_section/conner_section.urdf");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

ModelSpec Load(const std::string& section) {
  return test::LoadInline(ConnerUrdf(), "aero: {sections: {conner: {" + section + "}}}");
}

const std::string kValid = "plunge: plunge, pitch: pitch, flap: flap_hinge, semichord: 0.127, a: -0.5, c: 0.5, ";

TEST(AeroConfig, SectionWithDefaults) {
  const ModelSpec spec = Load(kValid + "velocity: 20.0");
  ASSERT_EQ(spec.aero_sections.size(), 1u);
  const AeroSectionSpec& s = spec.aero_sections[0];
  EXPECT_EQ(s.name, "conner");
  EXPECT_EQ(s.plunge, "plunge");
  EXPECT_EQ(s.pitch, "pitch");
  EXPECT_EQ(s.flap, "flap_hinge");
  EXPECT_EQ(s.semichord, 0.127);
  EXPECT_EQ(s.a, -0.5);
  EXPECT_EQ(s.c, 0.5);
  EXPECT_EQ(s.velocity, 20.0);
  EXPECT_EQ(s.density, 1.225);
  EXPECT_EQ(s.span, 1.0);
  EXPECT_EQ(s.inflow_states, 6);
  const Model model = BuildModel(spec);
  EXPECT_EQ(model.num_element_states(), 6);
  EXPECT_EQ(model.DescribeUnknown(model.element_state_unknown(0)), "aero section conner mu_1");
}

TEST(AeroConfig, AllKeysRead) {
  const ModelSpec spec = Load(kValid + "velocity: 20.0, density: 1.0, span: 0.5, inflow_states: 0");
  const AeroSectionSpec& s = spec.aero_sections.at(0);
  EXPECT_EQ(s.density, 1.0);
  EXPECT_EQ(s.span, 0.5);
  EXPECT_EQ(s.inflow_states, 0);
}

TEST(AeroConfig, UnknownKeyIsRejected) {
  EXPECT_CONFIG_ERROR(Load(kValid + "velocity: 20.0, chord: 0.25"),
                      "test.yaml: aero.sections.conner.chord: unknown key");
  EXPECT_CONFIG_ERROR(test::LoadInline(ConnerUrdf(), "aero: {section: {}}"), "test.yaml: aero.section: unknown key");
}

TEST(AeroConfig, MissingVelocityIsRejected) {
  EXPECT_CONFIG_ERROR(Load(kValid), "test.yaml: aero.sections.conner: missing key 'velocity'");
}

TEST(AeroConfig, UnknownJointIsRejected) {
  EXPECT_CONFIG_ERROR(Load("plunge: plunge, pitch: pich, flap: flap_hinge, semichord: 0.127, a: -0.5, c: 0.5, "
                           "velocity: 20.0"),
                      "test.yaml: aero.sections.conner.pitch: no joint 'pich' in test.urdf");
}

TEST(AeroConfig, NonphysicalValuesAreRejected) {
  EXPECT_CONFIG_ERROR(Load("plunge: plunge, pitch: pitch, flap: flap_hinge, semichord: -0.1, a: -0.5, c: 0.5, "
                           "velocity: 20.0"),
                      "test.yaml: aero.sections.conner.semichord: -0.1 is negative; expected a semichord > 0 [m]");
  EXPECT_CONFIG_ERROR(Load("plunge: plunge, pitch: pitch, flap: flap_hinge, semichord: 0.127, a: -1.5, c: 0.5, "
                           "velocity: 20.0"),
                      "test.yaml: aero.sections.conner.a: -1.5 is off the chord; expected the elastic axis a with "
                      "-1 < value < 1 (semichords aft of mid-chord)");
  EXPECT_CONFIG_ERROR(Load(kValid + "velocity: -3"), "test.yaml: aero.sections.conner.velocity: -3 is negative");
  EXPECT_CONFIG_ERROR(Load(kValid + "velocity: 20.0, density: 0"),
                      "test.yaml: aero.sections.conner.density: 0 is zero");
  EXPECT_CONFIG_ERROR(
      Load(kValid + "velocity: 20.0, inflow_states: 12"),
      "test.yaml: aero.sections.conner.inflow_states: 12 is too many; expected 0 <= inflow_states <= 10");
}

TEST(AeroConfig, WrongTypeIsRejected) {
  EXPECT_CONFIG_ERROR(Load(kValid + "velocity: fast"), "test.yaml: aero.sections.conner.velocity:");
  EXPECT_CONFIG_ERROR(Load(kValid + "velocity: 20.0, inflow_states: 2.5"),
                      "test.yaml: aero.sections.conner.inflow_states:");
}

// The same joint as pitch and flap passed every type and axis check and ran (explore23 bad/aero/pitch_is_flap.yaml:
// the Hodges-Pierce section fluttered at 48.17 m/s instead of 54.50).
TEST(AeroConfig, OneJointInTwoRolesIsRejected) {
  EXPECT_CONFIG_ERROR(Load("plunge: plunge, pitch: pitch, flap: pitch, semichord: 0.127, a: -0.5, c: 0.5, "
                           "velocity: 20.0"),
                      "test.yaml: aero.sections.conner.flap: joint 'pitch' is the section's pitch already; expected a "
                      "joint of its own for each of plunge, pitch and flap");
  EXPECT_CONFIG_ERROR(Load("plunge: plunge, pitch: plunge, flap: flap_hinge, semichord: 0.127, a: -0.5, c: 0.5, "
                           "velocity: 20.0"),
                      "test.yaml: aero.sections.conner.pitch: joint 'plunge' is the section's plunge already;");
}

TEST(AeroConfig, JointOfTheWrongTypeOrAxisIsRejectedAtBuild) {
  EXPECT_CONFIG_ERROR(
      BuildModel(Load("plunge: pitch, pitch: plunge, flap: flap_hinge, semichord: 0.127, a: -0.5, c: 0.5, "
                      "velocity: 20.0")),
      "aero.sections.conner.plunge: joint 'pitch' is not a prismatic joint; expected a prismatic joint");
  const std::string tilted =
      std::regex_replace(ConnerUrdf(), std::regex("<axis xyz=\"0 0 1\"/>"), "<axis xyz=\"1 0 0\"/>");
  EXPECT_CONFIG_ERROR(
      BuildModel(test::LoadInline(tilted, "aero: {sections: {conner: {" + kValid + "velocity: 20.0}}}")),
      "aero.sections.conner.plunge: joint 'plunge' moves along/about an axis at cosine 0 to the world z "
      "axis; expected the z axis");
}

// solver.eigen.sweep.airspeed (docs/config.md, "solver.eigen"): read in order, and refused when it cannot bracket a
// change of stability or has no section to blow on.
ModelSpec LoadSweep(const std::string& sweep, const std::string& eigen_extra = "") {
  return test::LoadInline(ConnerUrdf(), "aero: {sections: {conner: {" + kValid +
                                            "velocity: 20.0}}}\n"
                                            "solver: {analysis: eigen, eigen: {" +
                                            eigen_extra + "sweep: {" + sweep + "}}}");
}

TEST(AeroConfig, AirspeedSweepIsRead) {
  const ModelSpec spec = LoadSweep("airspeed: [10, 20.5, 30]", "static_first: true, ");
  EXPECT_EQ(spec.solver.eigen.sweep_airspeed, std::vector<double>({10.0, 20.5, 30.0}));
  EXPECT_TRUE(spec.solver.eigen.static_first);
  EXPECT_TRUE(spec.solver.eigen.sweep_velocity_scale.empty());
}

TEST(AeroConfig, BadAirspeedSweepIsRejected) {
  EXPECT_CONFIG_ERROR(LoadSweep("airspeed: []"),
                      "test.yaml: solver.eigen.sweep.airspeed: an empty list; expected at least one free-stream speed "
                      "[m/s]");
  EXPECT_CONFIG_ERROR(LoadSweep("airspeed: [10, -5]"),
                      "test.yaml: solver.eigen.sweep.airspeed[1]: -5 is negative; expected a free-stream speed > 0 "
                      "[m/s]");
  EXPECT_CONFIG_ERROR(LoadSweep("airspeed: [10, 30, 20]"),
                      "test.yaml: solver.eigen.sweep.airspeed[2]: 20 does not exceed the speed before it, 30; expected "
                      "speeds in increasing order [m/s]");
  EXPECT_CONFIG_ERROR(LoadSweep("airspeed: [10, 10.0]"),
                      "test.yaml: solver.eigen.sweep.airspeed[1]: 10.0 does not exceed the speed before it, 10;");
  EXPECT_CONFIG_ERROR(LoadSweep("airspeed: [10], velocity_scale: [1]"),
                      "test.yaml: solver.eigen.sweep: expected exactly one of velocity_scale");
  EXPECT_CONFIG_ERROR(LoadSweep("airspeed: [10]", "about: steady_state, "),
                      "test.yaml: solver.eigen.about: steady_state cannot go with an airspeed sweep");
}

TEST(AeroConfig, AirspeedSweepWithoutSectionsIsRejected) {
  EXPECT_CONFIG_ERROR(test::LoadInline(ConnerUrdf(), "solver: {analysis: eigen, eigen: {sweep: {airspeed: [10]}}}"),
                      "test.yaml: solver.eigen.sweep.airspeed: sweeps the free-stream speed of the aero sections and "
                      "strips, but there are none; expected aero.sections or aero.strips");
}

}  // namespace aero_config_test
}  // namespace flexmbd
