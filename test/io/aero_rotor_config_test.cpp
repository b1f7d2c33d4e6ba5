// `aero.rotors` (src/io/yaml_aero.cpp, docs/config.md "aero"): a rotor's uniform inflow read from YAML with its
// defaults, one inflow state whose unknown the blades' strips share, the harmonic inflow's three, and the messages
// of bad input. Reference: the
// values written in the inline documents below and config/goland_wing/goland_wing.urdf (its wing as a blade).

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "goland_wing_fixture.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace aero_rotor_config_test {

using test::GolandUrdf;
const std::string& kBeam = test::kGolandBeam;

ModelSpec LoadRotor(const std::string& rotor) {
  return test::LoadInline(GolandUrdf(), kBeam + "aero: {strips: {blade: {beam: wing, semichord: 0.9, a: -0.34, "
                                                "inflow_states: 2}}, rotors: {main: {" + rotor + "}}}");
}

TEST(AeroRotorConfig, RotorWithDefaultsSharesOneInflowStateWithItsStrips) {
  const ModelSpec spec = LoadRotor("strips: [blade], radius: 6.5");
  ASSERT_EQ(spec.aero_rotors.size(), 1u);
  const AeroRotorSpec& r = spec.aero_rotors[0];
  EXPECT_EQ(r.name, "main");
  EXPECT_EQ(r.strips, std::vector<std::string>{"blade"});
  EXPECT_EQ(r.radius, 6.5);
  EXPECT_EQ(r.axis, Vec3::UnitZ());
  EXPECT_EQ(r.inflow, AeroRotorSpec::Inflow::kUniform);
  EXPECT_EQ(r.center, Vec3::Zero());
  // Seven strips of two states each, then the rotor's inflow, which every strip reads as its last unknown.
  const Model model = BuildModel(spec);
  ASSERT_EQ(model.aero_rotors().size(), 1u);
  EXPECT_EQ(model.num_element_states(), 15);
  const int inflow = model.element_state_unknown(14);
  EXPECT_EQ(model.DescribeUnknown(inflow), "rotor main nu");
  EXPECT_EQ(model.aero_rotors()[0]->strips().size(), 7u);
  for (const BeamStripAero* strip : model.aero_strips()) EXPECT_EQ(strip->unknowns().back(), inflow);
}

TEST(AeroRotorConfig, HarmonicRotorSharesThreeInflowStatesWithItsStrips) {
  const ModelSpec spec = LoadRotor("strips: [blade], radius: 6.5, inflow: harmonic, center: [1, -2, 0.5]");
  const AeroRotorSpec& r = spec.aero_rotors.at(0);
  EXPECT_EQ(r.inflow, AeroRotorSpec::Inflow::kHarmonic);
  EXPECT_EQ(r.center, Vec3(1.0, -2.0, 0.5));
  // Seven strips of two states each, then nu_0, nu_c, nu_s, the last three unknowns of every strip.
  const Model model = BuildModel(spec);
  EXPECT_EQ(model.num_element_states(), 17);
  const char* names[] = {"rotor main nu", "rotor main nu_c", "rotor main nu_s"};
  for (int k = 0; k < 3; ++k) {
    const int unknown = model.element_state_unknown(14 + k);
    EXPECT_EQ(model.DescribeUnknown(unknown), names[k]);
    for (const BeamStripAero* strip : model.aero_strips()) EXPECT_EQ(strip->unknowns().end()[k - 3], unknown);
  }
}

// Two rotors whose order is not their strips': `main` (harmonic) has the second strip, `tail` (uniform) the first.
// The strips' states come first (7 nodes of 2 states, then 7 of none), then main's nu_0, nu_c, nu_s (14-16) and
// tail's nu (17); each rotor lists its own blade's strips, and those read its states.
TEST(AeroRotorConfig, EachRotorHasItsOwnBladesAndStates) {
  const Model model = BuildModel(test::LoadInline(
      GolandUrdf(), kBeam + "aero: {strips: {blade: {beam: wing, semichord: 0.9, a: -0.34, inflow_states: 2}, "
                            "other: {beam: wing, semichord: 0.9, a: -0.34, inflow_states: 0}}, "
                            "rotors: {main: {strips: [other], radius: 6.5, inflow: harmonic}, "
                            "tail: {strips: [blade], radius: 6.5}}}"));
  ASSERT_EQ(model.aero_rotors().size(), 2u);
  ASSERT_EQ(model.aero_strips().size(), 14u);
  EXPECT_EQ(model.num_element_states(), 18);
  const RotorInflow &main = *model.aero_rotors()[0], &tail = *model.aero_rotors()[1];
  EXPECT_EQ(main.name(), "main");
  const std::vector<const BeamStripAero*> blade(model.aero_strips().begin(), model.aero_strips().begin() + 7),
      other(model.aero_strips().begin() + 7, model.aero_strips().end());
  EXPECT_EQ(main.strips(), other);
  EXPECT_EQ(tail.strips(), blade);
  for (const BeamStripAero* strip : other) {
    EXPECT_EQ(strip->unknowns().end()[-3], model.element_state_unknown(14));
    EXPECT_EQ(strip->unknowns().back(), model.element_state_unknown(16));
  }
  for (const BeamStripAero* strip : blade) EXPECT_EQ(strip->unknowns().back(), model.element_state_unknown(17));
  EXPECT_EQ(model.DescribeUnknown(model.element_state_unknown(17)), "rotor tail nu");
}

TEST(AeroRotorConfig, AxisIsNormalised) {
  EXPECT_EQ(LoadRotor("strips: [blade], radius: 6.5, axis: [0, 0, -2]").aero_rotors.at(0).axis, -Vec3::UnitZ());
}

TEST(AeroRotorConfig, BadKeysAndValuesAreRejected) {
  EXPECT_CONFIG_ERROR(
      LoadRotor("strips: [blade], radius: 6.5, hub: spin"),
      "test.yaml: aero.rotors.main.hub: unknown key; valid keys are: strips, radius, axis, inflow, center");
  EXPECT_CONFIG_ERROR(LoadRotor("strips: [blade], radius: 6.5, inflow: skewed"),
                      "test.yaml: aero.rotors.main.inflow: 'skewed' is not a valid rotor inflow; expected one of "
                      "uniform, harmonic");
  EXPECT_CONFIG_ERROR(LoadRotor("strips: [blade], radius: 6.5, center: [0, 0]"),
                      "test.yaml: aero.rotors.main.center: [0, 0] has 2 entries; expected [x, y, z], a disc centre");
  EXPECT_CONFIG_ERROR(LoadRotor("strips: [blade]"), "test.yaml: aero.rotors.main: missing key 'radius'");
  EXPECT_CONFIG_ERROR(LoadRotor("radius: 6.5"), "test.yaml: aero.rotors.main: missing key 'strips'");
  EXPECT_CONFIG_ERROR(LoadRotor("strips: [], radius: 6.5"),
                      "test.yaml: aero.rotors.main.strips: lists no strip; expected the names of the blades' strips");
  EXPECT_CONFIG_ERROR(LoadRotor("strips: blade, radius: 6.5"), "test.yaml: aero.rotors.main.strips: ");
  EXPECT_CONFIG_ERROR(LoadRotor("strips: [blade], radius: 0"), "test.yaml: aero.rotors.main.radius: 0");
  EXPECT_CONFIG_ERROR(LoadRotor("strips: [blade], radius: 6.5, axis: [0, 0, 0]"),
                      "test.yaml: aero.rotors.main.axis: [0, 0, 0] has no direction; expected a non-zero shaft axis");
}

TEST(AeroRotorConfig, StripsMustBeUnderAeroStripsAndOnOneRotor) {
  EXPECT_CONFIG_ERROR(BuildModel(LoadRotor("strips: [blades], radius: 6.5")),
                      "aero.rotors.main.strips[0]: no strip 'blades'; expected a name under aero.strips");
  ModelSpec spec = LoadRotor("strips: [blade], radius: 6.5");
  spec.aero_rotors.push_back(spec.aero_rotors[0]);
  spec.aero_rotors[1].name = "tail";
  EXPECT_CONFIG_ERROR(BuildModel(spec), "aero.rotors.tail.strips[0]: strip 'blade' is already a blade of rotor "
                                        "'main'; expected each strip on one rotor at most");
}

// The wing, 6 m along x from the hub at the origin (2 elements: node 6 the tip), as the blade: the disc about a centre
// 4 m off the hub leaves the tip sqrt(6^2 + 4^2) = 7.21 m from the shaft axis; a radius short of the tip leaves it
// 6 m from the axis; the centre's place along the axis does not count (docs/theory.md, (A14)).
TEST(AeroRotorConfig, BladesMustLieWithinTheRadiusOfTheShaftAxisThroughTheCentre) {
  EXPECT_CONFIG_ERROR(BuildModel(LoadRotor("strips: [blade], radius: 6.5, inflow: harmonic, center: [0, 4, 0]")),
                      "test.yaml: aero.rotors.main.center: [0.000000, 4.000000, 0.000000] leaves node 6 of strip "
                      "'blade' 7.211103 m from the shaft axis through it, beyond the radius 6.500000 m; expected the "
                      "disc's centre on the shaft axis (the hub's), every blade node within the radius of it");
  EXPECT_CONFIG_ERROR(BuildModel(LoadRotor("strips: [blade], radius: 5.9")),
                      "test.yaml: aero.rotors.main.center: [0.000000, 0.000000, 0.000000] leaves node 6 of strip "
                      "'blade' 6.000000 m from the shaft axis through it, beyond the radius 5.900000 m");
  EXPECT_EQ(BuildModel(LoadRotor("strips: [blade], radius: 6.0, center: [0, 0, 40]")).aero_rotors().size(), 1u);
}

}  // namespace aero_rotor_config_test
}  // namespace flexmbd
