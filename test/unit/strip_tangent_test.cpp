// The beam strip's analytic tangent (docs/theory.md, (A7)-(A9)) against central differences of its residual: the
// whole scheme tangent of a mid-step (energy-decaying) step, and at the end point its stiffness part and its
// rate parts; on a Goland wing strip moving in every direction, in a gust, on a strip of the wing with aileron
// whose flap is the aileron's node at its station (A10), and on a strip of a rotor's blade with the rotor's inflow
// element (A13).

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "scheme_tangent_check.hpp"

namespace flexmbd {
namespace strip_tangent_test {

// The residual is at most quadratic in the rates (u times the downwash) and smooth in the rotations: central
// differences with steps of 1e-6 are good to ~1e-16 |r| / 1e-6 plus (1e-6)^2 times the third derivative
// through the rotations, ~1e-10 of the largest entry; 1e-7 leaves room.
constexpr double kStep = 1.0e-6, kTolerance = 1.0e-7;
// The residual is at most quadratic in the end rates and linear in the accelerations, for which central
// differences are exact: a larger step keeps the round-off of the ~1e4 N residual at 1e-16 * 1e4 / 1e-3 = 1e-9.
constexpr double kRateStep = 1.0e-3;

struct Strip {
  Model model;
  const BeamStripAero* element;
  State start;
};

// Every node turned and moving at random, the states and their rates nonzero: the strip at `index`.
Strip Shaken(ModelSpec spec, int index) {
  spec.aero_strips.at(0).inflow_states = 4;
  // A steady gust across the span axis too, so that every component of the relative air velocity is nonzero.
  spec.aero_flow.gust = Vec3(3.0, -4.0, 5.0);
  spec.aero_flow.gust_scale = TimeFunctionSpec();
  spec.aero_flow.gust_scale.kind = TimeFunctionSpec::Kind::kSine;
  spec.aero_flow.gust_scale.amplitude = 1.0;
  spec.aero_flow.gust_scale.frequency = 2.0;
  Strip s{BuildModel(spec), nullptr, State()};
  s.element = s.model.aero_strips().at(index);
  s.start = s.model.initial_state();
  test::Random random(7);
  for (NodeState& n : s.start.nodes) {
    n.R = n.R * Exp(random.Vector(0.2));
    n.v = random.Vector(5.0);
    n.w = random.Vector(2.0);
  }
  s.start.element_states = Eigen::VectorXd::LinSpaced(s.model.num_element_states(), 0.3, -0.2);
  s.start.element_state_rates = Eigen::VectorXd::LinSpaced(s.model.num_element_states(), 1.0, 2.0);
  return s;
}

Strip GolandStrip() {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/config/goland_wing/";
  return Shaken(LoadModelSpec(dir + "goland_wing.urdf", dir + "flutter_below.yaml"), 5);
}

// The strip at the wing's node 12, whose flap is the aileron's node 3 (config/wing_aileron).
Strip FlapStrip() {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/config/wing_aileron/";
  ModelSpec spec = LoadModelSpec(dir + "wing_aileron.urdf", dir + "flutter_sweep.yaml");
  return Shaken(spec, 12);
}

// The end-point stiffness and rate parts of `s` against differences, at t = 0.3 s with end speeds of 5 m/s.
void ExpectEndPointPartsMatchDifferences(const Strip& s) {
  test::ExpectEndPointPartsMatchDifferences(s.model, *s.element, s.start, 0.3, 5.0, kStep, kRateStep, kTolerance);
}

TEST(StripTangent, MidStepSchemeTangentMatchesDifferences) {
  const Strip s = GolandStrip();
  test::ExpectMidStepTangentMatchesDifferences(s.model, *s.element, s.start, kStep, kTolerance);
}

TEST(StripTangent, EndPointStiffnessAndRatePartsMatchDifferences) {
  ExpectEndPointPartsMatchDifferences(GolandStrip());
}

// The Goland strip with the stream reversed: air from the trailing edge (docs/theory.md, (A12)).
Strip ReversedGolandStrip() {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/config/goland_wing/";
  ModelSpec spec = LoadModelSpec(dir + "goland_wing.urdf", dir + "flutter_below.yaml");
  spec.aero_flow.free_stream = -spec.aero_flow.free_stream;
  return Shaken(spec, 5);
}

TEST(StripTangent, ReverseFlowMidStepSchemeTangentMatchesDifferences) {
  const Strip s = ReversedGolandStrip();
  test::ExpectMidStepTangentMatchesDifferences(s.model, *s.element, s.start, kStep, kTolerance);
}

TEST(StripTangent, ReverseFlowEndPointStiffnessAndRatePartsMatchDifferences) {
  ExpectEndPointPartsMatchDifferences(ReversedGolandStrip());
}

TEST(StripTangent, FlapMidStepSchemeTangentMatchesDifferences) {
  const Strip s = FlapStrip();
  ASSERT_EQ(s.element->num_local(), 12 + 4);
  test::ExpectMidStepTangentMatchesDifferences(s.model, *s.element, s.start, kStep, kTolerance);
}

TEST(StripTangent, FlapEndPointStiffnessAndRatePartsMatchDifferences) {
  const Strip s = FlapStrip();
  ASSERT_EQ(s.element->num_local(), 12 + 4);
  ExpectEndPointPartsMatchDifferences(s);
}

// The Goland wing made the blade of a rotor whose shaft leans off every axis (docs/theory.md, (A13)): the strip
// reads the rotor's inflow (the last element state) and adds its thrust to the inflow's row. With the harmonic
// inflow (A14) it reads the three states at its place, weighted by its position relative to a centre off every
// axis, and adds its thrust and moments to their rows.
Strip RotorStrip(AeroRotorSpec::Inflow inflow = AeroRotorSpec::Inflow::kUniform) {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/config/goland_wing/";
  ModelSpec spec = LoadModelSpec(dir + "goland_wing.urdf", dir + "flutter_below.yaml");
  AeroRotorSpec rotor;
  rotor.name = "rotor";
  rotor.strips = {spec.aero_strips.at(0).name};
  rotor.radius = 7.0;  // the tip stands 6.9 m from the leaning axis through the centre
  rotor.axis = Vec3(0.1, -0.2, 1.0).normalized();
  rotor.inflow = inflow;
  rotor.center = Vec3(-0.7, 1.3, 0.4);
  spec.aero_rotors.push_back(rotor);
  return Shaken(spec, 5);
}

const RotorInflow& Rotor(const Strip& s) { return *s.model.aero_rotors().at(0); }

TEST(StripTangent, RotorBladeMidStepSchemeTangentMatchesDifferences) {
  const Strip s = RotorStrip();
  ASSERT_EQ(s.element->num_local(), 6 + 4 + 1);
  test::ExpectMidStepTangentMatchesDifferences(s.model, *s.element, s.start, kStep, kTolerance);
  test::ExpectMidStepTangentMatchesDifferences(s.model, Rotor(s), s.start, kStep, kTolerance);
}

// The rotor's own element has no acceleration part (M = 0), which the end-point check cannot scale by: its
// stiffness and rate parts are checked together in the mid-step scheme tangent above.
TEST(StripTangent, RotorBladeEndPointStiffnessAndRatePartsMatchDifferences) {
  ExpectEndPointPartsMatchDifferences(RotorStrip());
}

Strip HarmonicRotorStrip() { return RotorStrip(AeroRotorSpec::Inflow::kHarmonic); }

TEST(StripTangent, HarmonicRotorBladeMidStepSchemeTangentMatchesDifferences) {
  const Strip s = HarmonicRotorStrip();
  ASSERT_EQ(s.element->num_local(), 6 + 4 + 3);
  test::ExpectMidStepTangentMatchesDifferences(s.model, *s.element, s.start, kStep, kTolerance);
  test::ExpectMidStepTangentMatchesDifferences(s.model, Rotor(s), s.start, kStep, kTolerance);
}

TEST(StripTangent, HarmonicRotorBladeEndPointStiffnessAndRatePartsMatchDifferences) {
  ExpectEndPointPartsMatchDifferences(HarmonicRotorStrip());
}

}  // namespace strip_tangent_test
}  // namespace flexmbd
