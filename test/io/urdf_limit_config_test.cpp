// YAML values checked against a joint's URDF <limit> (src/io/urdf_limit.cpp, docs/config.md "URDF mapping"): an
// initial position, a stop or a drive's path outside it gives a warning (ModelSpec::warnings). Reference: the <limit>
// and the values written in the inline documents below; degrees read with the double nearest pi / 180.

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace urdf_limit_config_test {
using test::LoadInline;

// A hinge about y with a URDF <limit> of [-0.5, 0.7] rad, a continuous hub and a slide along x within [-1, 1] m.
const std::string kUrdf = test::LimitedJointsUrdf();

ModelSpec Load(const std::string& yaml) { return LoadInline(kUrdf, yaml); }

TEST(UrdfLimitConfig, DegreesTypedUnderTheRadianKeyOfAnInitialPositionAreTakenWithAWarningNamingTheDegreeKey) {
  // 30 rad is outside [-0.5, 0.7] rad; 30 deg (0.52 rad) is inside it: the warning says which key takes degrees.
  const ModelSpec spec = Load("joints: {hinge: {initial: {position: 30}}}");
  EXPECT_EQ(spec.warnings, std::vector<std::string>{
                               "test.yaml: joints.hinge.initial.position: 30 [rad] is outside the URDF <limit> [-0.5, "
                               "0.7] [rad] of joint 'hinge': without stops (backlash) nothing holds the joint to its "
                               "<limit>; if 30 is in degrees, write position_deg: 30"});
}

TEST(UrdfLimitConfig, AnInitialPositionInDegreesOutsideTheLimitIsNamedInBothUnits) {
  EXPECT_EQ(Load("joints: {hinge: {initial: {position_deg: -60}}}").warnings,
            std::vector<std::string>{"test.yaml: joints.hinge.initial.position_deg: -60 [deg] (-1.0471975511965976 "
                                     "rad) is outside the URDF <limit> [-0.5, 0.7] [rad] of joint 'hinge': without "
                                     "stops (backlash) nothing holds the joint to its <limit>"});
}

TEST(UrdfLimitConfig, AnInitialSlideOutsideItsLimitIsNamedInMetres) {
  const ModelSpec spec = Load("joints: {slide: {variables: [{initial: {position: 1.5}}]}}");
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_EQ(spec.warnings[0].find("test.yaml: joints.slide.variables[0].initial.position: 1.5 [m] is outside the URDF "
                                  "<limit> [-1, 1] [m] of joint 'slide'"),
            0u)
      << spec.warnings[0];
}

TEST(UrdfLimitConfig, ADriveThatStartsOutsideTheLimitIsNamedOnceAtTheDrive) {
  EXPECT_EQ(Load("joints: {hinge: {drive: {law: linear_ramp, offset: 0.9, value: 0.0, duration: 1.0}}}").warnings,
            std::vector<std::string>{"test.yaml: joints.hinge.drive: the drive reaches 0.9 [rad] at t = 0 s, outside "
                                     "the URDF <limit> [-0.5, 0.7] [rad] of joint 'hinge' (solver.t_end 1 s): the "
                                     "drive, not the <limit>, sets the motion"});
}

double InitialPosition(const ModelSpec& spec, const std::string& joint) {
  for (const JointSpec& j : spec.joints) {
    if (j.name == joint) return j.initial_position.at(0);
  }
  throw std::runtime_error("no joint " + joint);
}

TEST(UrdfLimitConfig, InitialPositionsOnAndInsideTheLimitAndOnJointsWithoutOneAreTaken) {
  const ModelSpec on = Load("joints: {hinge: {initial: {position: 0.7}}, slide: {initial: {position: -1.0}}}");
  EXPECT_EQ(InitialPosition(on, "hinge"), 0.7);
  EXPECT_EQ(InitialPosition(on, "slide"), -1.0);
  EXPECT_TRUE(on.warnings.empty());
  // a continuous joint has no <limit>: any turn is a position
  EXPECT_EQ(InitialPosition(Load("joints: {spin: {initial: {position: 30.0}}}"), "spin"), 30.0);
}

TEST(UrdfLimitConfig, StopsOutsideTheLimitAreTakenWithAWarningEachThatNamesTheField) {
  const ModelSpec spec = Load("joints: {hinge: {backlash: {lower_deg: -40, upper: 30}}}");
  ASSERT_EQ(spec.warnings.size(), 2u);
  EXPECT_EQ(spec.warnings[0],
            "test.yaml: joints.hinge.backlash.lower_deg: -40 [deg] (-0.6981317007977318 rad) is outside the URDF "
            "<limit> [-0.5, 0.7] [rad] of joint 'hinge': this stop, not the <limit>, bounds the motion");
  EXPECT_EQ(spec.warnings[1],
            "test.yaml: joints.hinge.backlash.upper: 30 [rad] is outside the URDF <limit> [-0.5, 0.7] [rad] of joint "
            "'hinge': this stop, not the <limit>, bounds the motion; if 30 is in degrees, write upper_deg: 30");
}

TEST(UrdfLimitConfig, StopsInsideTheLimitOrFromItWarnOfNothing) {
  EXPECT_TRUE(Load("joints: {hinge: {backlash: {lower: -0.5, upper_deg: 10}}}").warnings.empty());
  EXPECT_TRUE(Load("joints: {hinge: {backlash: {radius_upper: 0.1}}}").warnings.empty());
}

TEST(UrdfLimitConfig, StopsGivenInTheYamlBoundTheInitialPositionInsteadOfTheLimit) {
  // Stops at +-1 rad, wider than the <limit>: a start at 0.9 rad lies between them (a warning per stop, none for the
  // start) ...
  const ModelSpec wide = Load("joints: {hinge: {initial: {position: 0.9}, backlash: {lower: -1.0, upper: 1.0}}}");
  EXPECT_EQ(wide.warnings.size(), 2u);
  EXPECT_NO_THROW(BuildModel(wide));
  // ... and one beyond them is refused by the model, at the stop it passes.
  EXPECT_CONFIG_ERROR(
      BuildModel(Load("joints: {hinge: {initial: {position: 1.2}, backlash: {lower: -1.0, upper: 1.0}}}")),
      "stop 'upper': the initial position 1.2 rad");
}

TEST(UrdfLimitConfig, ADriveThatLeavesTheLimitBeforeTheRunEndsIsTakenWithAWarning) {
  // A linear ramp from 0 to 1 rad over [0, 1] s passes the upper limit 0.7 rad at 0.7 s and holds 1 rad from 1 s on.
  const std::string drive = "joints: {hinge: {drive: {law: linear_ramp, value: 1.0, duration: 1.0}}}\n";
  const ModelSpec spec = Load(drive + "solver: {t_end: 2.0}");
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_EQ(spec.warnings[0],
            "test.yaml: joints.hinge.drive: the drive reaches 1 [rad] at t = 1 s, outside the URDF <limit> [-0.5, 0.7] "
            "[rad] of joint 'hinge' (solver.t_end 2 s): the drive, not the <limit>, sets the motion");
  // A run that ends at 0.5 s (0.5 rad), or an analysis that takes the drive at t = 0 only, stays within it.
  EXPECT_TRUE(Load(drive + "solver: {t_end: 0.5}").warnings.empty());
  EXPECT_TRUE(Load(drive + "solver: {analysis: static}").warnings.empty());
}

// The <limit> is read in the unit of the URDF's type: a revolute's in radians, a prismatic's in metres. A YAML type
// that gives variable 0 the other unit leaves it out, with a warning naming the file, the joint and both types: before,
// a revolute made prismatic took its [-0.5, 0.7] rad as metres, in the warnings and as default stops.
TEST(UrdfLimitConfig, ALimitInAnotherUnitThanTheYamlTypesVariableIsLeftOutWithAWarningNamingBothTypes) {
  const ModelSpec spec = Load("joints: {hinge: {type: prismatic, initial: {position: 0.9}}}");
  EXPECT_EQ(spec.warnings,
            std::vector<std::string>{
                "test.yaml: joints.hinge.type: the URDF's revolute joint 'hinge' made prismatic: its "
                "<limit> [-0.5, 0.7] is in rad, variable 0 of a prismatic joint in m; the <limit> is left "
                "out (no stops from it, no values checked against it)"});
  const ModelSpec slide = Load("joints: {slide: {type: revolute, backlash: {upper: 3.0}}}");
  ASSERT_EQ(slide.warnings.size(), 1u);
  EXPECT_EQ(
      slide.warnings[0].find("test.yaml: joints.slide.type: the URDF's prismatic joint 'slide' made revolute: its "
                             "<limit> [-1, 1] is in m, variable 0 of a revolute joint in rad;"),
      0u)
      << slide.warnings[0];
  // Stops from the <limit> would be in the wrong unit: a block without positions is refused, saying why.
  EXPECT_CONFIG_ERROR(
      Load("joints: {hinge: {type: prismatic, backlash: {stop: {type: rigid}}}}"),
      "test.yaml: joints.hinge.backlash: gives no stop position and the URDF <limit> of joint 'hinge' "
      "is not in m, the unit of variable 0 (s) of prismatic joint 'hinge'; expected lower and/or upper");
}

TEST(UrdfLimitConfig, ALimitStaysWhereTheYamlTypeKeepsItsUnitAndBoundsVariableZeroOnly) {
  // A revolute made cylindrical keeps its angle as variable 0 (phi): the <limit> applies to it, not to the slide s.
  const ModelSpec spec = Load("joints: {hinge: {type: cylindrical, initial: {position: 30}}}");
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_EQ(spec.warnings[0].find("test.yaml: joints.hinge.initial.position: 30 [rad] is outside the URDF <limit>"), 0u)
      << spec.warnings[0];
  EXPECT_CONFIG_ERROR(Load("joints: {hinge: {type: cylindrical, variables: [{}, {backlash: {stop: {type: rigid}}}]}}"),
                      "test.yaml: joints.hinge.variables[1].backlash: gives no stop position and the URDF <limit> of "
                      "joint 'hinge' bounds variable 0, not variable 1 (s) of cylindrical joint 'hinge'");
}

}  // namespace urdf_limit_config_test
}  // namespace flexmbd
