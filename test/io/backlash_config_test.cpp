// `joints.NAME.backlash` (src/io/yaml_backlash.cpp, docs/config.md "backlash"): stops read from YAML, the URDF
// <limit> used when a block gives no positions, and the exact messages of bad input. Reference: the values
// written in the inline documents below.

#include <gtest/gtest.h>

#include <cmath>

#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace backlash_config_test {
using test::LoadInline;

// A hinge about y with a URDF <limit> of [-0.5, 0.7] rad, a continuous hub and a slide along x within [-1, 1] m.
const std::string kUrdf = test::LimitedJointsUrdf();

ModelSpec Load(const std::string& yaml) { return LoadInline(kUrdf, yaml); }

const std::vector<StopSpec>& StopsOf(const ModelSpec& spec, const std::string& joint) {
  for (const JointSpec& j : spec.joints) {
    if (j.name == joint) return j.effects.at(0).stops;
  }
  throw std::runtime_error("no joint " + joint);
}

// Degrees are converted with the double nearest pi / 180: one rounding.
constexpr double kDegreeRoundOff = 1.0e-15;

TEST(BacklashConfig, BlockInDegreesWithRadiiAndHertzStop) {
  const ModelSpec spec = Load(R"(
joints:
  hinge:
    backlash: {lower_deg: -2.0, upper_deg: 3.0, radius_lower: 0.02, radius_upper: 0.03,
               stop: {type: elastic, law: hertz, stiffness: 6.85e6, exponent: 1.4, restitution: 0.8,
                      steps_per_contact: 30}}
)");
  const std::vector<StopSpec>& stops = StopsOf(spec, "hinge");
  ASSERT_EQ(stops.size(), 2u);
  EXPECT_EQ(stops[0].name, "lower");
  EXPECT_EQ(stops[0].side, StopSpec::Side::kLower);
  EXPECT_NEAR(stops[0].limit, -2.0 * M_PI / 180.0, kDegreeRoundOff);
  EXPECT_EQ(stops[0].radius, 0.02);
  EXPECT_EQ(stops[1].name, "upper");
  EXPECT_EQ(stops[1].side, StopSpec::Side::kUpper);
  EXPECT_NEAR(stops[1].limit, 3.0 * M_PI / 180.0, kDegreeRoundOff);
  EXPECT_EQ(stops[1].radius, 0.03);
  for (const StopSpec& stop : stops) {
    EXPECT_EQ(stop.kind, StopSpec::Kind::kElastic);
    EXPECT_EQ(stop.law, StopSpec::Law::kHertz);
    EXPECT_EQ(stop.stiffness, 6.85e6);
    EXPECT_EQ(stop.exponent, 1.4);
    EXPECT_EQ(stop.restitution, 0.8);
    EXPECT_EQ(stop.steps_per_contact, 30);
    EXPECT_TRUE(stop.retraction.joint.empty());
  }
}

TEST(BacklashConfig, BuiltStopsReportTheKindTheBlockAsked) {
  // JointStop::rigid(), which the static solver and the friction builder read: a rigid block's stops are
  // constraints, an elastic block's force laws.
  const Model model = BuildModel(Load(R"(
joints:
  hinge:
    backlash: [{lower: -0.4, upper: 0.6, stop: {type: rigid}},
               {lower: -0.45, upper: 0.65, stop: {type: elastic, law: linear, stiffness: 1.0e4}}]
)"));
  ASSERT_EQ(model.stop_effects().size(), 4u);
  for (size_t k = 0; k < 4; ++k) EXPECT_EQ(model.stop_effects()[k]->rigid(), k < 2) << model.stops()[k].stop;
}

TEST(BacklashConfig, UrdfLimitGivesThePositionsWhenTheBlockHasNone) {
  const std::vector<StopSpec> stops = StopsOf(Load("joints: {hinge: {backlash: {radius_upper: 0.1}}}"), "hinge");
  ASSERT_EQ(stops.size(), 2u);
  EXPECT_EQ(stops[0].limit, -0.5);
  EXPECT_EQ(stops[0].radius, 1.0);  // the default
  EXPECT_EQ(stops[0].kind, StopSpec::Kind::kRigid);
  EXPECT_EQ(stops[1].limit, 0.7);
  EXPECT_EQ(stops[1].radius, 0.1);
}

TEST(BacklashConfig, BlockWithoutPositionsNeedsAUrdfLimit) {
  EXPECT_CONFIG_ERROR(Load("joints: {spin: {backlash: {radius_lower: 0.1}}}"),
                      "test.yaml: joints.spin.backlash: gives no stop position and joint 'spin' has no URDF <limit>; "
                      "expected lower and/or upper (or lower_deg, upper_deg)");
}

TEST(BacklashConfig, ListOfBlocksNamesTheLaterOnesWithTheirIndex) {
  const std::vector<StopSpec> stops = StopsOf(Load(R"(
joints:
  hinge:
    backlash:
      - {lower: -0.1}
      - {upper: 0.2, retract: {joint: spin, above: 5.0, below: 2.0}}
)"),
                                              "hinge");
  ASSERT_EQ(stops.size(), 2u);
  EXPECT_EQ(stops[0].name, "lower");
  EXPECT_EQ(stops[0].limit, -0.1);
  EXPECT_EQ(stops[1].name, "upper.1");
  EXPECT_EQ(stops[1].limit, 0.2);
  EXPECT_EQ(stops[1].retraction.joint, "spin");
  EXPECT_EQ(stops[1].retraction.retract_above, 5.0);
  EXPECT_EQ(stops[1].retraction.engage_below, 2.0);
}

TEST(BacklashConfig, LowerNotBelowUpperIsRejected) {
  EXPECT_CONFIG_ERROR(Load("joints: {hinge: {backlash: {lower: 0.5, upper: 0.5}}}"),
                      "test.yaml: joints.hinge.backlash: lower 0.5 is not below upper 0.5 [rad]; expected lower < "
                      "upper");
}

TEST(BacklashConfig, NegativeRadiusIsRejected) {
  EXPECT_CONFIG_ERROR(Load("joints: {hinge: {backlash: {lower: -0.1, radius_lower: -0.02}}}"),
                      "test.yaml: joints.hinge.backlash.radius_lower: -0.02 is negative; expected a contact radius "
                      "> 0 [m]");
}

// Expects the message of an upper stop at 0.1 rad on the hinge whose `stop:` map holds `stop`.
void ExpectStopError(const std::string& stop, const std::string& message) {
  EXPECT_CONFIG_ERROR(Load("joints: {hinge: {backlash: {upper: 0.1, stop: {" + stop + "}}}}"), message);
}

TEST(BacklashConfig, NegativeOrZeroStiffnessIsRejected) {
  ExpectStopError("type: elastic, stiffness: -1.0e6",
                  "test.yaml: joints.hinge.backlash.stop.stiffness: -1.0e6 is negative; expected a contact stiffness "
                  "> 0 [N/m^n]");
  ExpectStopError("type: elastic, stiffness: 0",
                  "test.yaml: joints.hinge.backlash.stop.stiffness: 0 is zero; expected a contact stiffness > 0 "
                  "[N/m^n]");
}

TEST(BacklashConfig, RestitutionOutsideZeroToOneIsRejected) {
  ExpectStopError("type: elastic, stiffness: 1.0e6, restitution: 0",
                  "test.yaml: joints.hinge.backlash.stop.restitution: 0 is outside (0, 1]; expected a coefficient of "
                  "restitution in (0, 1]");
  ExpectStopError("type: elastic, stiffness: 1.0e6, restitution: 1.5",
                  "test.yaml: joints.hinge.backlash.stop.restitution: 1.5 is outside (0, 1]; expected a coefficient "
                  "of restitution in (0, 1]");
}

TEST(BacklashConfig, UnknownKeyIsRejectedWithASuggestion) {
  EXPECT_CONFIG_ERROR(Load("joints: {hinge: {backlash: {lower: -0.1, uper: 0.1}}}"),
                      "test.yaml: joints.hinge.backlash.uper: unknown key; did you mean 'upper'?");
}

TEST(BacklashConfig, RadiusOnAPrismaticJointIsRejected) {
  EXPECT_CONFIG_ERROR(Load("joints: {slide: {backlash: {lower: -0.5, radius_lower: 0.1}}}"),
                      "test.yaml: joints.slide.backlash.radius_lower: applies only to rotations; variable 0 (s) of "
                      "prismatic joint 'slide' is a translation, whose gap is its travel; expected no radius_lower");
}

TEST(BacklashConfig, RetractionBelowNotUnderAboveIsRejected) {
  EXPECT_CONFIG_ERROR(Load("joints: {hinge: {backlash: {upper: 0.1, retract: {joint: spin, above: 2.0, below: 2.0}}}}"),
                      "test.yaml: joints.hinge.backlash.retract.below: 2 is not below 'above' (2); expected below < "
                      "above");
}

TEST(BacklashConfig, DriveThroughARigidStopIsRejected) {
  // Found as a user: a slide driven from 0 to 2 m with a rigid stop at 1 m loaded, ran to 0.5 s and failed there
  // on a singular matrix ("step size fell below dt_min ... a drive on a fixed motion").
  EXPECT_CONFIG_ERROR(Load("joints: {slide: {drive: {law: linear_ramp, value: 2.0, duration: 1.0}, "
                           "backlash: {upper: 0.5}}}\nsolver: {t_end: 1.0}"),
                      "test.yaml: joints.slide.drive: the drive reaches 2 [m] at t = 1 s, beyond the rigid upper stop "
                      "at 0.5 [m] (solver.t_end 1 s): a prescribed motion cannot pass a rigid stop; expected a drive "
                      "that stays within its rigid stops up to solver.t_end, an elastic stop (the drive then presses "
                      "into it) or no stop there");
  EXPECT_CONFIG_ERROR(Load("joints: {hinge: {variables: [{drive: {law: sine, amplitude: 0.3, frequency: 1.0}, "
                           "backlash: [{lower: -0.2}, {lower: -0.4}]}]}}"),
                      "test.yaml: joints.hinge.variables[0].drive: the drive reaches -0.3 [rad] at t = 0.75 s, beyond "
                      "the rigid lower stop at -0.2 [rad]");
}

TEST(BacklashConfig, DriveOntoOrIntoAStopThatGivesWayIsAccepted) {
  // Up to the stop and no further (touching), into an elastic stop, past a rigid stop that retracts, or a path
  // that passes the stop only after t_end, or in a static analysis (which takes the drive at t = 0 only).
  for (const std::string joint :
       {"slide: {drive: {law: table, times: [0, 0.5], values: [0, 0.5]}, backlash: {upper: 0.5}}",
        "slide: {drive: {law: linear_ramp, value: 2.0}, backlash: {upper: 0.5, stop: {type: elastic, stiffness: 1e4}}}",
        "hinge: {drive: {law: linear_ramp, value: 0.6},"
        " backlash: {upper: 0.5, retract: {joint: spin, above: 2, below: 1}}}",
        "slide: {drive: {law: linear_ramp, value: 2.0, start: 1.0}, backlash: {upper: 0.5}}"}) {
    EXPECT_NO_THROW(Load("joints: {" + joint + "}\nsolver: {t_end: 1.0}")) << joint;
  }
  EXPECT_NO_THROW(Load("joints: {slide: {drive: {law: linear_ramp, value: 2.0}, backlash: {upper: 0.5}}}\n"
                       "solver: {analysis: static}"));
}

TEST(BacklashConfig, UnknownRetractionJointIsRejectedByBuildModel) {
  const ModelSpec spec = Load("joints: {hinge: {backlash: {upper: 0.1, retract: {joint: spinn, above: 2, below: 1}}}}");
  EXPECT_CONFIG_ERROR(BuildModel(spec), "joint 'hinge': stop 'upper': retract.joint 'spinn' is not a joint of the "
                                        "model; expected one of: hinge, slide, spin");
}

TEST(BacklashConfig, GeneralizedAlphaWithStopsIsRejectedByBuildModel) {
  const ModelSpec spec = Load("joints: {hinge: {backlash: {upper: 0.1}}}\nsolver: {integrator: generalized_alpha}");
  EXPECT_CONFIG_ERROR(BuildModel(spec), "solver.integrator: generalized_alpha does not support stops or friction; "
                                        "expected energy_decaying or energy_preserving");
}

}  // namespace backlash_config_test
}  // namespace flexmbd
