// Initial poses and velocities by forward kinematics (src/io/initial_placement.cpp). Reference: values
// computed by hand in each test from the rigid-body velocity field v_Q = v_P + w x (p_Q - p_P).

#include "flexmbd/io/initial_placement.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmbd/io/config_loader.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace initial_placement_test {
using test::DataPath;

// Poses and velocities of O(1) size built from a few dozen products of O(1) numbers, including cos(pi/2)
// = 6e-17 where the hand value is 0: rounding stays below 1e-15, so 1e-12 is tight yet robust.
constexpr double kTolerance = 1.0e-12;

const BodySpec& Body(const ModelSpec& spec, const std::string& name) {
  for (const BodySpec& body : spec.bodies) {
    if (body.name == name) return body;
  }
  throw std::runtime_error("no body " + name);
}

ModelSpec DoublePendulum() {
  return LoadModelSpec(DataPath("urdf/double_pendulum.urdf"), DataPath("yaml/double_pendulum.yaml"));
}

TEST(InitialPlacement, PendulumRotatedToInitialAngle) {
  const ModelSpec spec = LoadModelSpec(DataPath("urdf/pendulum.urdf"), DataPath("yaml/pendulum.yaml"));
  const BodySpec& rod = spec.bodies.at(0);
  Mat3 R_expected;  // Ry(30 deg)
  R_expected << std::sqrt(3.0) / 2.0, 0.0, 0.5, 0.0, 1.0, 0.0, -0.5, 0.0, std::sqrt(3.0) / 2.0;
  EXPECT_LT((rod.R_WB - R_expected).norm(), kTolerance);
  EXPECT_LT((rod.p_WB - Vec3(0.0, 0.0, 2.0)).norm(), kTolerance);
  EXPECT_LT(rod.v_WBo_W.norm(), kTolerance);
  EXPECT_LT(rod.w_WB_W.norm(), kTolerance);
}

TEST(InitialPlacement, DoublePendulumPoses) {
  // B1 at 90 deg turns arm1's x axis to -z; B2 at 90 deg (its drive's start) turns arm2's x axis to -x
  const ModelSpec spec = DoublePendulum();
  Mat3 R_arm1;
  R_arm1 << 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0;
  const Mat3 R_arm2 = Vec3(-1.0, 1.0, -1.0).asDiagonal();
  EXPECT_LT((Body(spec, "arm1").R_WB - R_arm1).norm(), kTolerance);
  EXPECT_LT((Body(spec, "arm1").p_WB - Vec3(0.0, 0.0, 2.0)).norm(), kTolerance);
  EXPECT_LT((Body(spec, "arm2").R_WB - R_arm2).norm(), kTolerance);
  EXPECT_LT((Body(spec, "arm2").p_WB - Vec3(0.0, 0.0, 1.0)).norm(), kTolerance);
}

TEST(InitialPlacement, DoublePendulumVelocities) {
  // arm1 turns at 2 rad/s about y; the B2 hinge, 1 m below B1, moves at (0,2,0) x (0,0,-1) = (-2,0,0);
  // arm2 adds its drive's initial rate pi rad/s
  const ModelSpec spec = DoublePendulum();
  EXPECT_LT((Body(spec, "arm1").w_WB_W - Vec3(0.0, 2.0, 0.0)).norm(), kTolerance);
  EXPECT_LT(Body(spec, "arm1").v_WBo_W.norm(), kTolerance);
  EXPECT_LT((Body(spec, "arm2").w_WB_W - Vec3(0.0, 2.0 + M_PI, 0.0)).norm(), kTolerance);
  EXPECT_LT((Body(spec, "arm2").v_WBo_W - Vec3(-2.0, 0.0, 0.0)).norm(), kTolerance);
}

TEST(InitialPlacement, SliderOnTurntableAddsRelativeAndTransportVelocity) {
  // turntable at 3 rad/s about z; block slides out along x at 0.25 m/s from 1 + 0.5 m:
  // v = 0.25 (radial) + 3 * 1.5 = 4.5 (tangential)
  const std::string urdf = test::WorldUrdf({"table", "block"}, R"(
    <joint name="turn" type="continuous"><parent link="world"/><child link="table"/><axis xyz="0 0 1"/></joint>
    <joint name="slide" type="prismatic"><parent link="table"/><child link="block"/><origin xyz="1 0 0"/>
      <axis xyz="1 0 0"/><limit lower="0" upper="2" effort="1" velocity="1"/></joint>)");
  const ModelSpec spec = test::LoadInline(urdf, R"(
    joints:
      turn: {initial: {velocity: 3.0}}
      slide: {initial: {position: 0.5, velocity: 0.25}})");
  const BodySpec& block = Body(spec, "block");
  EXPECT_LT((block.p_WB - Vec3(1.5, 0.0, 0.0)).norm(), kTolerance);
  EXPECT_LT((block.w_WB_W - Vec3(0.0, 0.0, 3.0)).norm(), kTolerance);
  EXPECT_LT((block.v_WBo_W - Vec3(0.25, 4.5, 0.0)).norm(), kTolerance);
}

TEST(InitialPlacement, ScrewAdvancesByPitchPerTurn) {
  // half a turn of a 2 mm screw rises 1 mm; one turn per second rises 2 mm/s
  const ModelSpec spec = LoadModelSpec(DataPath("urdf/screw.urdf"), DataPath("yaml/screw.yaml"));
  const BodySpec& nut = spec.bodies.at(0);
  EXPECT_LT((nut.p_WB - Vec3(0.0, 0.0, 0.101)).norm(), kTolerance);
  EXPECT_LT((nut.R_WB - Mat3(Vec3(-1.0, -1.0, 1.0).asDiagonal())).norm(), kTolerance);
  EXPECT_LT((nut.w_WB_W - Vec3(0.0, 0.0, 2.0 * M_PI)).norm(), kTolerance);
  EXPECT_LT((nut.v_WBo_W - Vec3(0.0, 0.0, 0.002)).norm(), kTolerance);
}

TEST(InitialPlacement, FloatingChildMovesRigidlyWithParent) {
  // l2 starts 1 m along x of l1, which turns at 1 rad/s about z: v = (0,0,1) x (1,0,0) = (0,1,0)
  const std::string urdf = test::WorldUrdf({"l1", "l2"}, R"(
    <joint name="j" type="continuous"><parent link="world"/><child link="l1"/><axis xyz="0 0 1"/></joint>
    <joint name="f" type="floating"><parent link="l1"/><child link="l2"/><origin xyz="1 0 0"/></joint>)");
  const BodySpec l2 = Body(test::LoadInline(urdf, "joints: {j: {initial: {velocity: 1.0}}}"), "l2");
  EXPECT_LT((l2.p_WB - Vec3(1.0, 0.0, 0.0)).norm(), kTolerance);
  EXPECT_LT((l2.w_WB_W - Vec3(0.0, 0.0, 1.0)).norm(), kTolerance);
  EXPECT_LT((l2.v_WBo_W - Vec3(0.0, 1.0, 0.0)).norm(), kTolerance);
}

TEST(InitialPlacement, ChildFrameOffsetFromJointFrame) {
  // revolute about z at the world origin, q = 90 deg, qdot = 1 rad/s; the joint frame sits at p_CJ = (1,0,0)
  // in the child, turned by R_CJ = Rz(90 deg): R_WC = Rz(90) Rz(90)^T = I, p_WC = -R_WC p_CJ = (-1,0,0),
  // v_WC = (0,0,1) x (-1,0,0) = (0,-1,0)
  JointSpec joint;
  joint.type = JointType::kRevolute;
  joint.axis_J = Vec3::UnitZ();
  joint.p_CJ = Vec3(1.0, 0.0, 0.0);
  joint.R_CJ << 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;
  joint.initial_position = {M_PI / 2.0};
  joint.initial_velocity = {1.0};
  const io::FrameMotion C = io::ChildMotion(io::FrameMotion{}, joint);
  EXPECT_LT((C.R_WF - Mat3::Identity()).norm(), kTolerance);
  EXPECT_LT((C.p_WF - Vec3(-1.0, 0.0, 0.0)).norm(), kTolerance);
  EXPECT_LT((C.w_WF_W - Vec3(0.0, 0.0, 1.0)).norm(), kTolerance);
  EXPECT_LT((C.v_WFo_W - Vec3(0.0, -1.0, 0.0)).norm(), kTolerance);
}

}  // namespace initial_placement_test
}  // namespace flexmbd
