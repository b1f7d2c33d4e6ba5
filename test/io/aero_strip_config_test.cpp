// `aero.strips`, `aero.free_stream`, `aero.density`, `aero.gust` (src/io/yaml_aero.cpp, docs/config.md "aero"):
// strips read from YAML with their defaults, one strip element per beam node, and the messages of bad input.
// Reference: the values written in the inline documents below, config/goland_wing/goland_wing.urdf and
// config/wing_aileron (the strips' flap).

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "goland_wing_fixture.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace aero_strip_config_test {

using test::GolandUrdf;
const std::string& kBeam = test::kGolandBeam;

ModelSpec Load(const std::string& aero) { return test::LoadInline(GolandUrdf(), kBeam + "aero: {" + aero + "}"); }

ModelSpec LoadStrip(const std::string& strip) { return Load("strips: {wing_strips: {" + strip + "}}"); }

const std::string kValid = "beam: wing, semichord: 0.9, a: -0.34";

TEST(AeroConfig, StripWithDefaults) {
  const ModelSpec spec = LoadStrip(kValid);
  ASSERT_EQ(spec.aero_strips.size(), 1u);
  const AeroStripSpec& s = spec.aero_strips[0];
  EXPECT_EQ(s.name, "wing_strips");
  EXPECT_EQ(s.beam, "wing");
  EXPECT_EQ(s.semichord, 0.9);
  EXPECT_EQ(s.a, -0.34);
  EXPECT_EQ(s.chord_axis, Vec3::UnitY());
  EXPECT_EQ(s.normal_axis, Vec3::UnitZ());
  EXPECT_EQ(s.inflow_states, 6);
  EXPECT_EQ(spec.aero_flow.free_stream, Vec3::Zero());
  EXPECT_EQ(spec.aero_flow.density, 1.225);
  EXPECT_EQ(spec.aero_flow.gust, Vec3::Zero());
  // Two cubic elements: seven nodes, a strip with six states on each.
  const Model model = BuildModel(spec);
  ASSERT_EQ(model.aero_strips().size(), 7u);
  EXPECT_EQ(model.num_element_states(), 42);
  EXPECT_EQ(model.DescribeUnknown(model.element_state_unknown(6)), "aero strip wing_strips node 1 mu_1");
}

TEST(AeroConfig, AllStripAndFlowKeysRead) {
  const ModelSpec spec = Load(
      "free_stream: [1.0, 100.0, 0.0], density: 0.9, gust: {velocity: [0, 0, 2.0], scale: {law: constant, value: "
      "0.5}}, strips: {wing_strips: {" +
      kValid + ", chord_axis: [0, 0, -2], normal_axis: [0, 1, 0], inflow_states: 0}}");
  const AeroStripSpec& s = spec.aero_strips.at(0);
  EXPECT_EQ(s.chord_axis, -Vec3::UnitZ());  // normalised
  EXPECT_EQ(s.normal_axis, Vec3::UnitY());
  EXPECT_EQ(s.inflow_states, 0);
  EXPECT_EQ(spec.aero_flow.free_stream, Vec3(1.0, 100.0, 0.0));
  EXPECT_EQ(spec.aero_flow.density, 0.9);
  EXPECT_EQ(spec.aero_flow.gust, Vec3(0.0, 0.0, 2.0));
  EXPECT_EQ(spec.aero_flow.gust_scale.value, 0.5);
}

TEST(AeroConfig, StripUnknownKeyIsRejected) {
  EXPECT_CONFIG_ERROR(LoadStrip(kValid + ", chord: 1.8"), "test.yaml: aero.strips.wing_strips.chord: unknown key");
  EXPECT_CONFIG_ERROR(Load("gust: {speed: [0, 0, 1]}"), "test.yaml: aero.gust.speed: unknown key");
}

TEST(AeroConfig, StripMissingKeyIsRejected) {
  EXPECT_CONFIG_ERROR(LoadStrip("beam: wing, a: -0.34"), "test.yaml: aero.strips.wing_strips: missing key 'semichord'");
  EXPECT_CONFIG_ERROR(Load("gust: {scale: {law: constant, value: 1}}"), "test.yaml: aero.gust: missing key 'velocity'");
}

TEST(AeroConfig, StripOnAnUnknownBeamIsRejected) {
  EXPECT_CONFIG_ERROR(LoadStrip("beam: wig, semichord: 0.9, a: -0.34"),
                      "test.yaml: aero.strips.wing_strips.beam: no beam 'wig' in test.urdf");
}

TEST(AeroConfig, StripOnAnUnknownBeamIsRejectedAtBuild) {
  ModelSpec spec = LoadStrip(kValid);
  spec.aero_strips[0].beam = "tail";
  EXPECT_CONFIG_ERROR(BuildModel(spec),
                      "aero.strips.wing_strips.beam: no beam 'tail'; expected a link under beams: (wing)");
}

TEST(AeroConfig, StripAxesMustCrossTheBeamAtRightAngles) {
  EXPECT_CONFIG_ERROR(LoadStrip(kValid + ", chord_axis: [1, 1, 0]"),
                      "test.yaml: aero.strips.wing_strips.chord_axis: [1, 1, 0] is not a direction across the beam; "
                      "expected a chord axis (leading to trailing edge) [0, y, z] in the beam's section frame");
  EXPECT_CONFIG_ERROR(LoadStrip(kValid + ", normal_axis: [0, 0, 0]"),
                      "test.yaml: aero.strips.wing_strips.normal_axis: [0, 0, 0] is not a direction across the beam");
  EXPECT_CONFIG_ERROR(LoadStrip(kValid + ", normal_axis: [0, 1, 1]"),
                      "test.yaml: aero.strips.wing_strips.normal_axis: [0, 1, 1] is not perpendicular to the chord "
                      "axis; expected chord_axis and normal_axis at right angles in the section frame");
}

TEST(AeroConfig, StripNonphysicalValuesAreRejected) {
  EXPECT_CONFIG_ERROR(LoadStrip("beam: wing, semichord: 0, a: -0.34"),
                      "test.yaml: aero.strips.wing_strips.semichord: 0 is zero; expected a semichord > 0 [m]");
  EXPECT_CONFIG_ERROR(LoadStrip("beam: wing, semichord: 0.9, a: 1"),
                      "test.yaml: aero.strips.wing_strips.a: 1 is off the chord; expected the elastic axis (beam "
                      "axis) a with -1 < value < 1 (semichords aft of mid-chord)");
  EXPECT_CONFIG_ERROR(
      LoadStrip(kValid + ", inflow_states: 11"),
      "test.yaml: aero.strips.wing_strips.inflow_states: 11 is too many; expected 0 <= inflow_states <= 10");
  EXPECT_CONFIG_ERROR(Load("density: -1"),
                      "test.yaml: aero.density: -1 is negative; expected an air density > 0 [kg/m^3]");
  EXPECT_CONFIG_ERROR(Load("free_stream: [0, 100]"), "test.yaml: aero.free_stream:");
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(std::string(FLEXMBD_SOURCE_DIR) + path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// config/wing_aileron/flutter_eigen.yaml with its strip's flap written as `flap`.
ModelSpec LoadWingAileron(const std::string& flap) {
  std::string yaml = ReadFile("/config/wing_aileron/flutter_eigen.yaml");
  const std::string written = "flap: {beam: aileron, c: 0.5}";
  yaml.replace(yaml.find(written), written.size(), "flap: {" + flap + "}");
  return test::LoadInline(ReadFile("/config/wing_aileron/wing_aileron.urdf"), yaml);
}

TEST(AeroConfig, StripFlapTakesTheAileronNodesAtItsStations) {
  const ModelSpec spec = LoadWingAileron("beam: aileron, c: 0.5");
  EXPECT_EQ(spec.aero_strips.at(0).flap.beam, "aileron");
  EXPECT_EQ(spec.aero_strips.at(0).flap.c, 0.5);
  // The aileron's seven nodes stand at the wing's nodes 9 to 15 (10 ft to 16.67 ft of 20 ft, 18 node spacings):
  // those strips couple the two nodes' unknowns (12) to their six states.
  const Model model = BuildModel(spec);
  ASSERT_EQ(model.aero_strips().size(), 19u);
  for (int k = 0; k < 19; ++k) {
    EXPECT_EQ(model.aero_strips()[k]->num_local(), (k >= 9 && k <= 15 ? 12 : 6) + 6) << "strip " << k;
  }
}

TEST(AeroConfig, StripFlapBadKeysAreRejected) {
  EXPECT_CONFIG_ERROR(LoadWingAileron("beam: aileron"), "test.yaml: aero.strips.wing.flap: missing key 'c'");
  EXPECT_CONFIG_ERROR(LoadWingAileron("beam: aileron, c: 0.5, chord: 0.2"),
                      "test.yaml: aero.strips.wing.flap.chord: unknown key");
  EXPECT_CONFIG_ERROR(LoadWingAileron("beam: flap, c: 0.5"),
                      "test.yaml: aero.strips.wing.flap.beam: no beam 'flap' in test.urdf");
  EXPECT_CONFIG_ERROR(
      LoadWingAileron("beam: wing, c: 0.5"),
      "test.yaml: aero.strips.wing.flap.beam: wing carries the strips; expected the control surface's beam");
  EXPECT_CONFIG_ERROR(
      LoadWingAileron("beam: aileron, c: 1.0"),
      "test.yaml: aero.strips.wing.flap.c: 1.0 is off the chord; expected the flap hinge c with -1 < value < 1");
}

TEST(AeroConfig, StripFlapOffTheHingeLineIsRejectedAtBuild) {
  // c = 0.4 puts the hinge line 0.9144 (0.4 + 1/3) = 0.6706 m aft of the axis; the aileron stands 0.762 m aft.
  EXPECT_CONFIG_ERROR(BuildModel(LoadWingAileron("beam: aileron, c: 0.4")),
                      "m above the axis of 'wing'; expected it on the hinge line, b (c - a) = 0.670560 m aft");
}

TEST(AeroConfig, StripStationsStandBetweenTheNodesStrips) {
  // Two cubic elements of 3 m: nodes every 1 m. A station at 2.25 m lies a quarter of the way from node 2 to
  // node 3; the tip station takes the tip node alone.
  ModelSpec spec = test::LoadInline(GolandUrdf(), kBeam + "aero: {strips: {wing_strips: {" + kValid +
                                                      "}}}\noutput: {strip_stations: {wing_strips: [0.0, 2.25, 6.0]}}");
  const Model model = BuildModel(spec);
  ASSERT_EQ(model.strip_stations().size(), 3u);
  const StripStationInfo& between = model.strip_stations()[1];
  EXPECT_EQ(between.strip, "wing_strips");
  EXPECT_EQ(between.index, 1);
  EXPECT_EQ(between.inner, model.aero_strips()[2]);
  EXPECT_EQ(between.outer, model.aero_strips()[3]);
  EXPECT_NEAR(between.weight, 0.25, 1.0e-15);
  const StripStationInfo& tip = model.strip_stations()[2];
  EXPECT_EQ(tip.inner, model.aero_strips()[6]);
  EXPECT_EQ(tip.outer, model.aero_strips()[6]);
  EXPECT_EQ(model.strip_stations()[0].inner, model.aero_strips()[0]);
  EXPECT_EQ(model.strip_stations()[0].weight, 0.0);
}

TEST(AeroConfig, StripStationsNameAStripAndStandOnItsBeam) {
  const std::string strips = kBeam + "aero: {strips: {wing_strips: {" + kValid + "}}}\n";
  EXPECT_CONFIG_ERROR(test::LoadInline(GolandUrdf(), strips + "output: {strip_stations: {wing: [1.0]}}"),
                      "test.yaml: output.strip_stations.wing: no strip 'wing' in aero.strips; strips are: wing_strips");
  EXPECT_CONFIG_ERROR(test::LoadInline(GolandUrdf(), strips + "output: {strip_stations: {wing_strips: [6.5]}}"),
                      "test.yaml: output.strip_stations.wing_strips[0]: 6.5 is beyond the tip; expected 0 <= s <= 6 "
                      "[m] (the length of beam wing)");
  EXPECT_CONFIG_ERROR(test::LoadInline(GolandUrdf(), strips + "output: {strip_stations: {wing_strips: [-1]}}"),
                      "test.yaml: output.strip_stations.wing_strips[0]");
  EXPECT_CONFIG_ERROR(
      test::LoadInline(GolandUrdf(), kBeam + "output: {strip_stations: {wing_strips: [1.0]}}"),
      "test.yaml: output.strip_stations.wing_strips: no strip 'wing_strips' in aero.strips; strips are: (none)");
  ModelSpec spec = test::LoadInline(GolandUrdf(), strips);
  spec.output.strip_stations["tail"] = {1.0};
  EXPECT_CONFIG_ERROR(BuildModel(spec),
                      "output.strip_stations.tail: no strip 'tail'; expected a name under aero.strips");
}

TEST(AeroConfig, StripAirspeedSweepNeedsTheStreamsDirection) {
  EXPECT_CONFIG_ERROR(
      test::LoadInline(GolandUrdf(), kBeam + "aero: {strips: {wing_strips: {" + kValid +
                                         "}}}\nsolver: {analysis: eigen, eigen: {sweep: {airspeed: [10]}}}"),
      "test.yaml: solver.eigen.sweep.airspeed: sweeps the strips' free-stream speed along "
      "aero.free_stream, which is zero; expected aero.free_stream to give the stream's direction");
}

}  // namespace aero_strip_config_test
}  // namespace flexmbd
