// Bad input: every case throws ConfigError with a one-line message naming the file, the field path, the
// offending value and the expected form (docs/config.md). Reference: the message texts of the loader.

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace config_errors_test {
using test::DataPath;
using test::LoadDataUrdf;
using test::LoadInline;

ModelSpec Pendulum(const std::string& yaml) { return LoadDataUrdf("pendulum.urdf", yaml, "pendulum.yaml"); }

ModelSpec DoublePendulum(const std::string& yaml) {
  return LoadDataUrdf("double_pendulum.urdf", yaml, "double_pendulum.yaml");
}

// A prismatic joint 'slide' along x between the world and one body 'block'.
const std::string kSliderUrdf = test::WorldUrdf({"block"}, R"(
  <joint name="slide" type="prismatic"><parent link="world"/><child link="block"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>)");

// URDF

TEST(ConfigErrors, MalformedUrdfIsRejected) {
  EXPECT_CONFIG_ERROR(LoadModelSpec(DataPath("urdf/malformed_invalid.urdf"), ""),
                      "malformed_invalid.urdf: not a valid URDF (urdfdom could not parse it)");
}

TEST(ConfigErrors, MovingLinkWithoutInertiaIsRejected) {
  EXPECT_CONFIG_ERROR(
      LoadModelSpec(DataPath("urdf/no_inertia_invalid.urdf"), ""),
      "no_inertia_invalid.urdf: link 'l2' moves (joint 'j2') but has no <inertial>; expected mass and inertia");
}

TEST(ConfigErrors, NegativeMassNamesLink) {
  EXPECT_CONFIG_ERROR(LoadModelSpec(DataPath("urdf/negative_mass_invalid.urdf"), ""),
                      "negative_mass_invalid.urdf: link 'l1': mass -2 is not positive; expected a mass > 0 [kg]");
}

// One link 'l1' of 1 kg on a hinge, with the given principal moments [kg m^2].
std::string OneLinkWithMoments(const std::string& ixx, const std::string& iyy, const std::string& izz) {
  return R"(<robot name="bad">
    <link name="world"/>
    <link name="l1"><inertial><mass value="1"/>
      <inertia ixx=")" +
         ixx + R"(" ixy="0" ixz="0" iyy=")" + iyy + R"(" iyz="0" izz=")" + izz + R"("/></inertial></link>
    <joint name="j1" type="continuous"><parent link="world"/><child link="l1"/><axis xyz="0 0 1"/></joint>
  </robot>)";
}

TEST(ConfigErrors, IndefiniteInertiaIsRejected) {
  EXPECT_CONFIG_ERROR(
      LoadInline(OneLinkWithMoments("1", "-1", "1"), ""),
      "test.urdf: link 'l1': <inertia> has principal moments [-1, 1, 1]; expected a positive semi-definite");
}

TEST(ConfigErrors, InertiaBeyondTheTriangleInequalityIsRejected) {
  // Positive definite, but izz > ixx + iyy: no distribution of mass has it (izz = ixx + iyy is a flat plate's).
  EXPECT_CONFIG_ERROR(LoadInline(OneLinkWithMoments("0.01", "0.1", "0.5"), ""),
                      "test.urdf: link 'l1': <inertia> has principal moments [0.01, 0.1, 0.5]; expected each principal "
                      "moment at most the sum of the other two");
}

TEST(ConfigErrors, NegativeUrdfDampingIsRejected) {
  const std::string urdf = test::WorldUrdf({"l1"}, R"(
    <joint name="j1" type="continuous"><parent link="world"/><child link="l1"/><axis xyz="0 0 1"/>
      <dynamics damping="-0.5"/></joint>)");
  EXPECT_CONFIG_ERROR(
      LoadInline(urdf, ""),
      "test.urdf: joint 'j1': <dynamics damping> -0.5 is negative; expected a damping >= 0 [N m s/rad]");
}

// The YAML makes the joint universal and gives no friction: the message says whose friction it is.
TEST(ConfigErrors, UrdfFrictionOnAJointTheYamlRetypesNamesTheUrdf) {
  const std::string urdf = test::WorldUrdf({"l1"}, R"(
    <joint name="j1" type="continuous"><parent link="world"/><child link="l1"/><axis xyz="0 0 1"/>
      <dynamics friction="0.5"/></joint>)");
  EXPECT_CONFIG_ERROR(BuildModel(LoadInline(urdf, "joints: {j1: {type: universal}}")),
                      "joint 'j1/0': friction: the URDF's <dynamics friction> on a universal joint; expected friction "
                      "on a revolute or prismatic joint");
}

// A joint made spherical has no variable for the URDF's damper and friction: they were dropped without a word
// (explore23 bad/urdf_fric_sph.yaml dissipated 0 J) where a screw or cylindrical joint refuses the friction.
TEST(ConfigErrors, UrdfDynamicsOnAJointMadeSphericalIsRejected) {
  const std::string urdf = test::WorldUrdf({"l1"}, R"(
    <joint name="j1" type="continuous"><parent link="world"/><child link="l1"/><axis xyz="0 0 1"/>
      <dynamics damping="0.2" friction="0.5"/></joint>)");
  EXPECT_CONFIG_ERROR(LoadInline(urdf, "joints: {j1: {type: spherical}}"),
                      "test.yaml: joints.j1.type: a spherical joint 'j1' has no variable to carry the URDF's "
                      "<dynamics damping> and <dynamics friction>; expected no <dynamics> on a joint made spherical");
  const std::string damped = test::WorldUrdf({"l1"}, R"(
    <joint name="j1" type="continuous"><parent link="world"/><child link="l1"/><axis xyz="0 0 1"/>
      <dynamics damping="0.2"/></joint>)");
  EXPECT_CONFIG_ERROR(LoadInline(damped, "joints: {j1: {type: spherical}}"),
                      "has no variable to carry the URDF's <dynamics damping>; expected");
}

// Names the variable as joint_states does, and gives the angles in the degrees the YAML used as well.
TEST(ConfigErrors, InitialPositionBeyondAStopNamesTheVariableAndTheUnits) {
  EXPECT_CONFIG_ERROR(BuildModel(Pendulum("joints: {B1: {type: universal, variables: [{}, {initial: {position_deg: "
                                          "30.0}, backlash: {lower_deg: -10.0, upper_deg: 10.0}}]}}")),
                      "pendulum.yaml: joint 'B1/1': stop 'upper': the initial position 0.523599 rad (30 deg) is "
                      "beyond the stop at 0.174533 rad (10 deg); expected an initial position inside the stops");
}

TEST(ConfigErrors, MissingFileCannotBeOpened) {
  EXPECT_CONFIG_ERROR(LoadModelSpec(DataPath("urdf/no_such_file.urdf"), ""), "cannot open URDF file '");
}

// YAML: documents and keys

TEST(ConfigErrors, YamlSyntaxErrorGivesLine) {
  EXPECT_CONFIG_ERROR(LoadModelSpec(DataPath("urdf/pendulum.urdf"), DataPath("yaml/syntax_invalid.yaml")),
                      "syntax_invalid.yaml: line 4, column 7: not valid YAML (end of map flow not found)");
}

TEST(ConfigErrors, UnknownJointListsJoints) {
  EXPECT_CONFIG_ERROR(DoublePendulum("joints: {B7: {damper: {c: 1.0}}}"),
                      "double_pendulum.yaml: joints.B7: no joint 'B7' in double_pendulum.urdf; joints are: B1, B2");
}

TEST(ConfigErrors, FrameJointHasNothingToConfigure) {
  EXPECT_CONFIG_ERROR(DoublePendulum("joints: {tip_frame: {type: revolute}}"),
                      "joints.tip_frame: joint 'tip_frame' of double_pendulum.urdf has nothing to configure: it fixes "
                      "link 'tip', which has no <inertial>, as a frame on body 'arm2'");
}

TEST(ConfigErrors, UnknownKeySuggestsClosest) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {dtt: 0.01}"), "pendulum.yaml: solver.dtt: unknown key; did you mean 'dt'?");
}

TEST(ConfigErrors, UnknownKeyListsValidKeys) {
  EXPECT_CONFIG_ERROR(Pendulum("output: {video: a.mp4}"),
                      "pendulum.yaml: output.video: unknown key; valid keys are: rate_hz, csv, bag");
}

TEST(ConfigErrors, CycleReportAfterTheEndIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("solver: {t_end: 2.0}\noutput: {cycle_from: 2.0}"),
      "pendulum.yaml: output.cycle_from: 2.0 s is not before solver.t_end 2 s; expected a time in [0, t_end)");
}

TEST(ConfigErrors, CycleReportNeedsEquallySpacedSamples) {
  EXPECT_CONFIG_ERROR(
      Pendulum("output: {rate_hz: 0, cycle_from: 0.5}"),
      "pendulum.yaml: output.cycle_from: needs equally spaced samples, and output.rate_hz is 0 (every step); "
      "expected rate_hz > 0");
}

TEST(ConfigErrors, NegativeCycleReportStartIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("output: {cycle_from: -1.0}"), "pendulum.yaml: output.cycle_from: -1");
}

TEST(ConfigErrors, EigenTimesNeedADynamicRun) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {analysis: static, eigen: {at_times: [0.5]}}"),
                      "pendulum.yaml: solver.eigen.at_times: applies to analysis: dynamic (the modes about the state "
                      "at times of the run); expected no at_times with another analysis");
}

TEST(ConfigErrors, EigenTimeAfterTheEndIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: 2.0, eigen: {at_times: [1.0, 2.5]}}"),
                      "pendulum.yaml: solver.eigen.at_times[1]: 2.5 s is after solver.t_end 2 s; expected times in "
                      "[0, t_end]");
}

TEST(ConfigErrors, EigenTimesOutOfOrderAreRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: 2.0, eigen: {at_times: [1.0, 1.0]}}"),
                      "pendulum.yaml: solver.eigen.at_times[1]: 1.0 s is not after the previous time 1 s; expected "
                      "increasing times [s]");
}

TEST(ConfigErrors, NegativeEigenTimeIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {eigen: {at_times: [-0.5]}}"), "pendulum.yaml: solver.eigen.at_times[0]: -0.5");
}

TEST(ConfigErrors, EigenTimesCannotGoWithASteadyState) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {eigen: {about: steady_state, at_times: [0.5]}}"),
                      "pendulum.yaml: solver.eigen.about: cannot go with at_times (the state analysed is the run's); "
                      "expected no about");
}

TEST(ConfigErrors, KineticAboveStaticFrictionIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {friction: {mu_s: 0.1, mu_k: 0.2}}}"),
                      "pendulum.yaml: joints.B1.friction.mu_s: 0.1 is below mu_k 0.2; expected mu_s >= mu_k");
}

TEST(ConfigErrors, NegativeFrictionRadiusPreloadOrSpeedIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {friction: {mu_k: 0.2, radius: -0.01}}}"),
                      "pendulum.yaml: joints.B1.friction.radius: -0.01 is negative; expected a race radius > 0 [m]");
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {friction: {mu_k: 0.2, preload: -1}}}"),
                      "pendulum.yaml: joints.B1.friction.preload: -1 is negative; expected a preload >= 0 [N]");
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {friction: {mu_k: 0.2, v0: -1e-3}}}"),
                      "pendulum.yaml: joints.B1.friction.v0: -1e-3 is negative; expected a sticking speed >= 0 [m/s]");
}

TEST(ConfigErrors, FrictionNeedsKineticCoefficient) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {friction: {mu_s: 0.2}}}"),
                      "pendulum.yaml: joints.B1.friction: missing key 'mu_k'; expected a friction coefficient >= 0");
}

TEST(ConfigErrors, RegularisedFrictionNeedsSpeed) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {friction: {law: regularised, mu_k: 0.2}}}"),
                      "pendulum.yaml: joints.B1.friction: missing key 'v0'; expected a regularisation speed > 0 [m/s] "
                      "for the regularised law");
}

TEST(ConfigErrors, DuplicateKeyIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {dt: 0.01, dt: 0.02}"), "pendulum.yaml: solver.dt: duplicate key");
}

// YAML: values

TEST(ConfigErrors, NegativeStiffnessIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {spring: {k: -3}}}"),
                      "pendulum.yaml: joints.B1.spring.k: -3 is negative; expected a stiffness >= 0 [N m/rad]");
}

TEST(ConfigErrors, WrongTypeNamesFieldAndExpectedType) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: long}"),
                      "pendulum.yaml: solver.t_end: 'long' is not a number; expected an end time > 0 [s]");
}

// explore6 D5: yaml-cpp read a quoted "100" as the number 100 and "true" or yes as a boolean; docs/config.md promises
// YAML 1.2's plain numbers and booleans.
TEST(ConfigErrors, QuotedNumberIsTextNotANumber) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {spring: {k: \"100\"}}}"),
                      "pendulum.yaml: joints.B1.spring.k: \"100\" is quoted, which makes it a text; expected a "
                      "stiffness >= 0 [N m/rad], written without quotes");
  EXPECT_CONFIG_ERROR(Pendulum("solver: {max_iterations: '20'}"),
                      "pendulum.yaml: solver.max_iterations: \"20\" is quoted, which makes it a text; expected an "
                      "iteration count >= 1, written without quotes");
}

TEST(ConfigErrors, QuotedBooleanIsTextNotABoolean) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {static_first: \"true\"}"),
                      "pendulum.yaml: solver.static_first: \"true\" is quoted, which makes it a text; expected true "
                      "or false, written without quotes");
}

TEST(ConfigErrors, Yaml11BooleansAreRefused) {
  for (const std::string word : {"yes", "no", "on", "off", "y"}) {
    EXPECT_CONFIG_ERROR(Pendulum("solver: {adaptive: " + word + "}"),
                        "pendulum.yaml: solver.adaptive: '" + word + "' is not a boolean; expected true or false");
  }
}

TEST(ConfigErrors, Yaml12BooleansAreRead) {
  EXPECT_FALSE(Pendulum("solver: {adaptive: FALSE}").solver.adaptive);
  EXPECT_TRUE(Pendulum("solver: {adaptive: True}").solver.adaptive);
}

TEST(ConfigErrors, NumberBeyondTheRangeOfADoubleIsSaidToBeOne) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {spring: {k: 1e400}}}"),
                      "pendulum.yaml: joints.B1.spring.k: 1e400 is a number beyond the range of a double");
}

TEST(ConfigErrors, EmptyValueIsNotADefault) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {damper: {c: }}}"),
                      "pendulum.yaml: joints.B1.damper.c: an empty value is not a number");
}

TEST(ConfigErrors, FractionalCountIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("solver: {max_iterations: 2.5}"),
      "pendulum.yaml: solver.max_iterations: '2.5' is not an integer; expected an iteration count >= 1");
}

TEST(ConfigErrors, CountsThatWouldRunForHoursAreRejected) {
  // A fuzz finding (seed 18, input 474): a static analysis of 2e9 load steps ran past the time limit.
  EXPECT_CONFIG_ERROR(Pendulum("solver: {analysis: static, load_steps: 2000000000}"),
                      "pendulum.yaml: solver.load_steps: 2000000000 is above 10000; expected at most 10000 load steps");
  EXPECT_CONFIG_ERROR(Pendulum("solver: {max_iterations: 1001}"),
                      "pendulum.yaml: solver.max_iterations: 1001 is above 1000; expected at most 1000 Newton "
                      "iterations per step");
  EXPECT_NO_THROW(Pendulum("solver: {load_steps: 10000, max_iterations: 1000}"));
}

TEST(ConfigErrors, ThreadCountIsAtLeastOneAndAtMost256) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {threads: 0}"),
                      "pendulum.yaml: solver.threads: 0 is less than 1; expected a thread count >= 1");
  EXPECT_CONFIG_ERROR(Pendulum("solver: {threads: 257}"),
                      "pendulum.yaml: solver.threads: 257 is above 256; expected at most 256 threads");
  EXPECT_NO_THROW(Pendulum("solver: {threads: 256}"));
}

TEST(ConfigErrors, RhoInfOutsideUnitIntervalIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {rho_inf: 1.5}"), "pendulum.yaml: solver.rho_inf: 1.5 is outside [0, 1]");
}

TEST(ConfigErrors, VectorOfWrongLengthIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {gravity: [0, -9.81]}"),
                      "pendulum.yaml: solver.gravity: [0, -9.81] has 2 entries; expected [x, y, z]");
}

TEST(ConfigErrors, UnknownChoiceSuggestsClosest) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {drive: {law: sinus}}}"),
                      "pendulum.yaml: joints.B1.drive.law: 'sinus' is not a valid law; expected one of constant, "
                      "linear_ramp, cosine_ramp, rate_ramp, sine, table; did you mean 'sine'?");
}

TEST(ConfigErrors, DegreesOnPrismaticVariableAreRejected) {
  EXPECT_CONFIG_ERROR(LoadInline(kSliderUrdf, "joints: {slide: {initial: {position_deg: 5}}}"),
                      "test.yaml: joints.slide.initial.position_deg: degrees apply only to angles; variable 0 (s) of "
                      "prismatic joint 'slide' is not an angle: use 'position' [m]");
}

TEST(ConfigErrors, BothSiAndDegreeFormsAreRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {initial: {position: 0.1, position_deg: 5}}}"),
                      "pendulum.yaml: joints.B1.initial.position_deg: both 'position' and 'position_deg' are given");
}

// YAML: joints

TEST(ConfigErrors, ScrewWithoutPitchIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {type: screw}}"),
      "pendulum.yaml: joints.B1: missing key 'pitch'; expected a screw pitch [m/rev] for a screw joint");
}

TEST(ConfigErrors, PitchOnRevoluteIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {pitch: 0.01}}"),
                      "pendulum.yaml: joints.B1.pitch: applies only to screw joints; this is a revolute joint 'B1'");
}

TEST(ConfigErrors, UniversalWithParallelAxesIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {type: universal, axis2: [0, 2, 0]}}"),
                      "pendulum.yaml: joints.B1.axis2: [0, 2, 0] is parallel to the joint axis [0, 1, 0]; expected a "
                      "second axis not parallel to the first");
}

TEST(ConfigErrors, ZeroAxisFromYamlIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {axis: [0, 0, 0]}}"),
                      "pendulum.yaml: joints.B1: joint 'B1': axis is zero; expected a non-zero 3-vector");
}

TEST(ConfigErrors, EffectOnJointWithoutVariablesIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {type: spherical, spring: {k: 1}}}"),
                      "pendulum.yaml: joints.B1.spring: the spherical joint 'B1' has no relative-motion variables");
}

TEST(ConfigErrors, ShorthandAndVariablesOnSameKeyAreRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {spring: {k: 1}, variables: [{spring: {k: 2}}]}}"),
      "pendulum.yaml: joints.B1.variables[0].spring: variable 0 is also configured by joints.B1.spring");
}

TEST(ConfigErrors, TooManyVariableEntriesAreRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {variables: [{}, {}]}}"),
      "pendulum.yaml: joints.B1.variables: has 2 entries; the revolute joint 'B1' has 1 variable(s) (phi)");
}

TEST(ConfigErrors, InitialPositionOffTheDriveIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {initial: {position: 0.1}, drive: {law: constant, value: 0.2}}}"),
      "pendulum.yaml: joints.B1.initial: position 0.1 [rad] differs from the drive's position 0.2 [rad] at t = 0; "
      "expected a driven variable to start on its drive");
}

TEST(ConfigErrors, InitialPositionBeyondResolutionIsRejected) {
  // A fuzz finding (seed 17, input 64,118): B1 of the antenna at -9e10 deg stepped at round-off for ever.
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {initial: {position_deg: -9.0e10}}}"),
                      "pendulum.yaml: joints.B1.initial.position_deg: an initial position of -1570796326.7948966 "
                      "[rad] is beyond what the solver resolves; expected an initial position within +-1e+06 [rad]");
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {drive: {law: constant, value: 2.0e6}}}"),
                      "pendulum.yaml: joints.B1.drive: an initial position of 2e+06 [rad] is beyond what the "
                      "solver resolves; expected an initial position within +-1e+06 [rad]");
  EXPECT_NO_THROW(Pendulum("joints: {B1: {initial: {position: -1.0e6}}}"));
}

TEST(ConfigErrors, InitialVelocityOffTheDriveIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {initial: {velocity: 1}, drive: {law: linear_ramp, value: 2, duration: 4}}}"),
      "pendulum.yaml: joints.B1.initial: velocity 1 [rad/s] differs from the drive's velocity 0.5 [rad/s] at t = 0");
}

// YAML: time functions

TEST(ConfigErrors, NonIncreasingTableIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {drive: {law: table, times: [0, 0.5, 0.5], values: [0, 1, 2]}}}"),
      "pendulum.yaml: joints.B1.drive.times[2]: 0.5 is not greater than the previous time 0.5; expected "
      "strictly increasing times [s]");
}

TEST(ConfigErrors, TableSizesMustMatch) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {drive: {law: table, times: [0, 1, 2], values_deg: [0, 1]}}}"),
      "pendulum.yaml: joints.B1.drive.values_deg: has 2 entries but times has 3; expected one value per time");
}

TEST(ConfigErrors, KeyOfAnotherLawIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("joints: {B1: {drive: {law: constant, amplitude: 1}}}"),
      "pendulum.yaml: joints.B1.drive.amplitude: does not apply to law 'constant'; it takes: law, value, value_deg");
}

TEST(ConfigErrors, SineWithoutItsAmplitudeOrFrequencyIsRejected) {
  // Both defaulted to 0, which made the sine a constant without a word.
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {drive: {law: sine, frequency: 2}}}"),
                      "pendulum.yaml: joints.B1.drive: missing key 'amplitude' (or amplitude_deg); expected the "
                      "sine's amplitude [rad] (a sine without it is a constant: law: constant)");
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {drive: {law: sine, amplitude_deg: 10, frequency: 0}}}"),
                      "pendulum.yaml: joints.B1.drive.frequency: 0 is zero; expected a frequency > 0 [Hz]");
  EXPECT_NO_THROW(Pendulum("joints: {B1: {drive: {law: sine, amplitude: 0, frequency: 2}}}"));
}

TEST(ConfigErrors, EmptyBacklashListIsRejected) {
  // It meant no stops without a word, though the key asks for them.
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {backlash: []}}"),
                      "pendulum.yaml: joints.B1.backlash: [] gives no stops; expected a backlash block or a list of "
                      "them (no key: no stops)");
}

TEST(ConfigErrors, NonPositiveRampDurationIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("joints: {B1: {drive: {law: cosine_ramp, value: 1, duration: 0}}}"),
                      "pendulum.yaml: joints.B1.drive.duration: 0 is zero; expected a duration > 0 [s]");
}

// YAML: solver and loads

TEST(ConfigErrors, DtAboveDtMaxIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {dt: 0.5, dt_max: 0.1}"),
                      "pendulum.yaml: solver.dt: 0.5 is greater than dt_max 0.1; expected dt_min <= dt <= dt_max [s]");
}

TEST(ConfigErrors, DtAboveDefaultDtMaxSaysDefault) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {dt: 0.5}"),
                      "pendulum.yaml: solver.dt: 0.5 is greater than dt_max 0.1 (default)");
}

TEST(ConfigErrors, LoadWithForceAndMomentIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("loads: [{body: rod, force: [1, 0, 0], moment: [0, 0, 1]}]"),
                      "pendulum.yaml: loads[0]: gives both 'force' and 'moment'; expected exactly one of them");
}

TEST(ConfigErrors, NewlineInAGivenNameKeepsTheMessageOneLine) {
  // fuzz finding (test/fuzz): the unknown name was quoted as written and its newline split the message
  EXPECT_CONFIG_ERROR(Pendulum("loads: [{body: \"line\\nbreak\", force: [1, 0, 0]}]"),
                      "pendulum.yaml: loads[0].body: no body or beam 'line\\nbreak' in pendulum.urdf");
  EXPECT_CONFIG_ERROR(Pendulum("joints: {\"B\\n1\": {damper: {c: 1.0}}}"), "pendulum.yaml: joints.B\\n1: ");
}

TEST(ConfigErrors, LoadOnUnknownBodyListsBodies) {
  EXPECT_CONFIG_ERROR(Pendulum("loads: [{body: rdo, force: [1, 0, 0]}]"),
                      "pendulum.yaml: loads[0].body: no body or beam 'rdo' in pendulum.urdf; bodies and beams are: "
                      "rod; did you mean 'rod'?");
}

TEST(ConfigErrors, PointOnMomentIsRejected) {
  EXPECT_CONFIG_ERROR(Pendulum("loads: [{body: rod, moment: [0, 0, 1], point: [1, 0, 0]}]"),
                      "pendulum.yaml: loads[0].point: applies only to forces");
}

TEST(ConfigErrors, NonMapDocumentIsRejected) {
  EXPECT_CONFIG_ERROR(
      Pendulum("just text"),
      "pendulum.yaml: 'just text' is not a map; expected a map with keys beams, joints, solver, output, loads, aero");
}

TEST(ConfigErrors, ErrorFloorIsReadAndChecked) {
  const SolverSpec solver =
      Pendulum("solver: {error_floor: {position: 1.0e-9, rotation: 2.0e-9, joint: 3.0e-9}}").solver;
  EXPECT_EQ(solver.error_floor.position, 1.0e-9);
  EXPECT_EQ(solver.error_floor.rotation, 2.0e-9);
  EXPECT_EQ(solver.error_floor.joint, 3.0e-9);
  EXPECT_CONFIG_ERROR(Pendulum("solver: {error_floor: {position: -1.0}}"),
                      "pendulum.yaml: solver.error_floor.position");
  EXPECT_CONFIG_ERROR(Pendulum("solver: {error_floor: {angle: 1.0}}"), "pendulum.yaml: solver.error_floor.angle");
}

}  // namespace config_errors_test
}  // namespace flexmbd
