// YAML `closures:` (docs/config.md): joints that close kinematic loops, read on the slider-crank of test/data.

#include <gtest/gtest.h>

#include <cmath>

#include "io_test_util.hpp"

namespace flexmbd {
namespace {

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

TEST(ClosureConfig, LoopThatDoesNotCloseIsRejected) {
  // The crank turned to 1 rad carries the rod (a spherical pin has no variable) away from the slide.
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_pin: {type: spherical}, crank_hinge: {initial: {position: 1.0}}}"),
                      "slider_crank.urdf + test.yaml: closures.wrist_pin: the loop does not close: the child's "
                      "joint frame lies [");
}

TEST(ClosureConfig, InitialMotionThatOpensTheLoopIsRejected) {
  EXPECT_CONFIG_ERROR(Load(kClosure + "joints: {crank_pin: {type: spherical}, crank_hinge: {initial: {velocity: 1.0}}}"),
                      "slider_crank.urdf + test.yaml: closures.wrist_pin: the initial motion opens the loop: "
                      "relative to the parent's joint frame the child moves at [0, -0.4, 0] m/s");
}

TEST(ClosureConfig, BadClosuresAreRejectedNamingTheField) {
  EXPECT_CONFIG_ERROR(Load("closures: {wrist_pin: {type: universal, parent: rod, child: slider, origin: [0, 0, 0]}}"),
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

}  // namespace
}  // namespace flexmbd
