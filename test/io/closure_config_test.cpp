// YAML `closures:` (docs/config.md): joints that close kinematic loops, read on the slider-crank of test/data.

#include <gtest/gtest.h>

#include <cmath>

#include "../verification/closed_forms.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace closure_config_test {

const std::string kClosure =
    "closures: {wrist_pin: {type: universal, parent: rod, child: slider, xyz: [0.3, 0.0, 0.0], axis: [0, 0, 1], "
    "axis2: [0, 1, 0]}}\n";
const std::string kSphericalPin = "joints: {crank_pin: {type: spherical}}\n";

ModelSpec Load(const std::string& yaml) {
  return test::LoadInline(test::ReadDataText("urdf/slider_crank.urdf"), yaml, "slider_crank.urdf", "test.yaml");
}

const JointSpec& Find(const ModelSpec& spec, const std::string& name) {
  for (const JointSpec& joint : spec.joints) {
    if (joint.name == name) return joint;
  }
  throw std::runtime_error("no joint " + name);
}

TEST(ClosureConfig, ClosureJoinsTheTwoBodiesAfterTheTreesJoints) {
  const ModelSpec spec = Load(kClosure + kSphericalPin);
  ASSERT_EQ(spec.joints.size(), 4u);
  const JointSpec& closure = spec.joints.back();
  EXPECT_EQ(closure.name, "wrist_pin");
  EXPECT_TRUE(closure.closes_loop);
  EXPECT_EQ(closure.type, JointType::kUniversal);
  EXPECT_EQ(closure.parent, "rod");
  EXPECT_EQ(closure.child, "slider");
  EXPECT_TRUE(closure.p_PJ.isApprox(Vec3(0.3, 0.0, 0.0)));
  EXPECT_TRUE(closure.p_CJ.isZero());  // the child link's frame, as a URDF joint's
  // the frames coincide as placed: both variables start at zero, at rest
  ASSERT_EQ(closure.initial_position.size(), 2u);
  EXPECT_NEAR(closure.initial_position[0], 0.0, 1e-12);
  EXPECT_NEAR(closure.initial_position[1], 0.0, 1e-12);
  EXPECT_EQ(closure.initial_velocity, std::vector<double>(2, 0.0));
  for (const JointSpec& joint : spec.joints) EXPECT_EQ(joint.closes_loop, joint.name == "wrist_pin");
}

TEST(ClosureConfig, InitialVariablesAreFittedToThePlacedBodies) {
  // The parent's joint frame turned by -0.3 rad about z: the slider's frame lies at +0.3 rad about the first
  // axis of the universal joint, which is where the fit puts its first variable (to the fit's round-off).
  const ModelSpec spec = Load(
      "closures: {wrist_pin: {type: universal, parent: rod, child: slider, xyz: [0.3, 0.0, 0.0], rpy: [0, 0, -0.3], "
      "axis: [0, 0, 1], axis2: [0, 1, 0]}}\n" + kSphericalPin);
  const JointSpec& closure = Find(spec, "wrist_pin");
  EXPECT_NEAR(closure.initial_position[0], 0.3, 1e-12);
  EXPECT_NEAR(closure.initial_position[1], 0.0, 1e-12);
}

TEST(ClosureConfig, InitialRatesAreFittedToTheTreesMotion) {
  // A revolute closure from the world to the crank, about the crank's own axis: the crank's initial rate
  // through the tree is the closure's rate.
  const ModelSpec spec = Load(
      "closures: {second_bearing: {type: revolute, parent: world, child: crank, axis: [0, 0, 1]}}\n"
      "joints: {crank_hinge: {initial: {velocity: 2.0}}}\n");
  const JointSpec& closure = Find(spec, "second_bearing");
  EXPECT_NEAR(closure.initial_velocity[0], 2.0, 1e-12);
}

TEST(ClosureConfig, ClosureTakesEffectsUnderJoints) {
  const ModelSpec spec = Load(kClosure + "joints: {crank_pin: {type: spherical}, wrist_pin: {spring: {k: 2.0}}}\n");
  const JointSpec& closure = Find(spec, "wrist_pin");
  ASSERT_EQ(closure.effects[0].springs.size(), 1u);
  EXPECT_EQ(closure.effects[0].springs[0].stiffness, 2.0);
}

// The slider-crank of test/data: crank 0.1 m, rod 0.3 m.
double SliderTravel(double theta) { return test::SliderTravel(0.1, 0.3, theta); }
double SliderTravelRate(double theta) { return test::SliderTravelRate(0.1, 0.3, theta); }
// The assembly stops at gaps of 1e-14 of the model's extent (1 m here); the slider's travel follows through
// the loop's lever ratios (below 2): 1e-12 m leaves a margin. Rates: one least-squares solve, round-off.
constexpr double kAssembledTolerance = 1.0e-12;

TEST(ClosureConfig, TreeJointsNotSetAreMovedToCloseTheLoop) {
  // The crank set at 1 rad: the slide and the spherical crank pin, not set, move until the universal wrist pin
  // closes; the crank keeps its angle.
  for (const std::string angle : {"1.0", "2.5", "-2.0"}) {
    const ModelSpec spec =
        Load(kClosure + "joints: {crank_pin: {type: spherical}, crank_hinge: {initial: {position: " + angle + "}}}");
    const double theta = std::stod(angle);
    EXPECT_DOUBLE_EQ(Find(spec, "crank_hinge").initial_position[0], theta);
    EXPECT_NEAR(Find(spec, "slide").initial_position[0], SliderTravel(theta), kAssembledTolerance) << angle;
  }
}

TEST(ClosureConfig, RatesNotSetAreMovedToKeepTheLoopClosed) {
  const ModelSpec spec =
      Load(kClosure + "joints: {crank_pin: {type: spherical}, crank_hinge: {initial: {position: 1.0, velocity: 2.0}}}");
  EXPECT_DOUBLE_EQ(Find(spec, "crank_hinge").initial_velocity[0], 2.0);
  EXPECT_NEAR(Find(spec, "slide").initial_velocity[0], 2.0 * SliderTravelRate(1.0), kAssembledTolerance);
}

TEST(ClosureConfig, DrivenJointIsHeldAtItsDrivesStart) {
  // A linear ramp from 1 rad at 2 pi rad/s: the assembly holds the crank at f(0) and its rate at f'(0).
  const ModelSpec spec = Load(kClosure + "joints: {crank_pin: {type: spherical}, crank_hinge: {drive: "
                                         "{law: linear_ramp, offset: 1.0, value: 7.283185307179586, duration: 1.0}}}");
  EXPECT_DOUBLE_EQ(Find(spec, "crank_hinge").initial_position[0], 1.0);
  EXPECT_NEAR(Find(spec, "slide").initial_position[0], SliderTravel(1.0), kAssembledTolerance);
  EXPECT_NEAR(Find(spec, "slide").initial_velocity[0], 2.0 * M_PI * SliderTravelRate(1.0), kAssembledTolerance);
}

TEST(ClosureConfig, LoopThatDoesNotCloseIsRejected) {
  // The crank at 1 rad leaves the rod's far end 0.058 m short of the slider, set at its start: only the pin's
  // rotation is free, which cannot close that.
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_pin: {type: spherical}, crank_hinge: {initial: {position: 1.0}}, "
                                      "slide: {initial: {position: 0.0}}}"),
                      "slider_crank.urdf + test.yaml: closures.wrist_pin: the loop does not close: the child's "
                      "joint frame lies [");
  // with a revolute crank pin and the slide set, the loop is redundant in the plane and the set angle conflicts
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_hinge: {initial: {position: 1.0}}, slide: {initial: "
                                      "{position: 0.0}}}"),
                      "closures.wrist_pin: the loop does not close");
}

TEST(ClosureConfig, InitialMotionThatOpensTheLoopIsRejected) {
  // The crank turning at 1 rad/s at 1 rad drives the slider, which is set at rest.
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_pin: {type: spherical}, crank_hinge: {initial: {position: 1.0, "
                                      "velocity: 1.0}}, slide: {initial: {velocity: 0.0}}}"),
                      "slider_crank.urdf + test.yaml: closures.wrist_pin: the initial motion opens the loop: "
                      "relative to the parent's joint frame the child moves at [");
}

TEST(ClosureConfig, BadClosuresAreRejectedNamingTheField) {
  EXPECT_CONFIG_ERROR(
      Load("closures: {wrist_pin: {type: universal, parent: rod, child: slider, origin: [0, 0, 0]}}"),
      "test.yaml: closures.wrist_pin.origin: unknown key; valid keys are: type, parent, child, xyz, rpy, "
      "child_xyz, child_rpy, axis, axis2, pitch");
  EXPECT_CONFIG_ERROR(Load("closures: {wrist_pin: {parent: rod, child: slider}}"),
                      "test.yaml: closures.wrist_pin: missing key 'type'");
  EXPECT_CONFIG_ERROR(Load("closures: {wrist_pin: {type: universal, parent: rdo, child: slider}}"),
                      "test.yaml: closures.wrist_pin.parent: no link 'rdo' in slider_crank.urdf");
  EXPECT_CONFIG_ERROR(Load("closures: {wrist_pin: {type: revolute, parent: slider, child: world}}"),
                      "test.yaml: closures.wrist_pin.child: link 'world' is fixed to the ground; expected a link "
                      "that moves");
  EXPECT_CONFIG_ERROR(Load("closures: {wrist_pin: {type: revolute, parent: rod, child: rod}}"),
                      "test.yaml: closures.wrist_pin: parent and child are both on 'rod'");
  EXPECT_CONFIG_ERROR(Load("closures: {slide: {type: revolute, parent: rod, child: slider}}"),
                      "test.yaml: closures.slide: a joint of that name exists already");
  EXPECT_CONFIG_ERROR(Load("closures: {\"wrist,pin\": {type: revolute, parent: rod, child: slider}}"),
                      "the name contains a comma");
  EXPECT_CONFIG_ERROR(Load("closures: {wrist_pin: {type: hinge, parent: rod, child: slider}}"),
                      "test.yaml: closures.wrist_pin.type:");
  EXPECT_CONFIG_ERROR(Load("closures: {wrist_pin: {type: revolute, parent: rod, child: slider, axis: [0, 0, 0]}}"),
                      "test.yaml: closures.wrist_pin");
  EXPECT_CONFIG_ERROR(Load("closures: [wrist_pin]"), "test.yaml: closures: ");
}

TEST(ClosureConfig, ClosuresMotionIsNotSetUnderJoints) {
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_pin: {type: spherical}, wrist_pin: {initial: {position: 0.1}}}"),
                      "test.yaml: joints.wrist_pin.initial: the universal joint 'wrist_pin' closes a loop "
                      "(closures.wrist_pin): its motion follows from the joints of the tree");
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_pin: {type: spherical}, wrist_pin: {drive: {law: constant}}}"),
                      "test.yaml: joints.wrist_pin.drive: the universal joint 'wrist_pin' closes a loop");
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_pin: {type: spherical}, wrist_pin: {type: revolute}}"),
                      "test.yaml: joints.wrist_pin.type: the universal joint 'wrist_pin' is a closure: its geometry "
                      "is given under closures.wrist_pin");
}

}  // namespace closure_config_test
}  // namespace flexmbd
