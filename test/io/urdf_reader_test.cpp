// URDF -> bodies and joints (src/io/urdf_reader.cpp); reference: the URDF files' values, mapped by the rules
// of docs/config.md "URDF mapping".

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace urdf_reader_test {
using test::DataPath;

// Values copied from the URDF or rotated by one exact quarter turn: only rounding of a few products.
constexpr double kTolerance = 1.0e-12;

ModelSpec LoadUrdfOnly(const std::string& file) { return LoadModelSpec(DataPath("urdf/" + file), ""); }

const BodySpec& Body(const ModelSpec& spec, const std::string& name) {
  for (const BodySpec& body : spec.bodies) {
    if (body.name == name) return body;
  }
  throw std::runtime_error("no body " + name);
}

const JointSpec& Joint(const ModelSpec& spec, const std::string& name) {
  for (const JointSpec& joint : spec.joints) {
    if (joint.name == name) return joint;
  }
  throw std::runtime_error("no joint " + name);
}

TEST(UrdfReader, PendulumBodyAtCenterOfMass) {
  const ModelSpec spec = LoadUrdfOnly("pendulum.urdf");
  ASSERT_EQ(spec.bodies.size(), 1u);
  const BodySpec& rod = spec.bodies[0];
  EXPECT_EQ(rod.name, "rod");
  EXPECT_EQ(rod.mass, 2.0);
  EXPECT_TRUE(rod.p_BoBcm_B.isApprox(Vec3(0.0, 0.0, -0.5)));
  EXPECT_TRUE(rod.inertia_cm_B.isApprox(Vec3(0.17, 0.17, 0.001).asDiagonal().toDenseMatrix()));
}

TEST(UrdfReader, PendulumJointHingedToWorld) {
  const ModelSpec spec = LoadUrdfOnly("pendulum.urdf");
  ASSERT_EQ(spec.joints.size(), 1u);
  const JointSpec& joint = spec.joints[0];
  EXPECT_EQ(joint.name, "B1");
  EXPECT_EQ(joint.type, JointType::kRevolute);
  EXPECT_EQ(joint.parent, "");
  EXPECT_EQ(joint.child, "rod");
  EXPECT_TRUE(joint.p_PJ.isApprox(Vec3(0.0, 0.0, 2.0)));
  EXPECT_TRUE(joint.R_PJ.isIdentity());
  EXPECT_TRUE(joint.p_CJ.isZero());
  EXPECT_TRUE(joint.R_CJ.isIdentity());
  EXPECT_TRUE(joint.axis_J.isApprox(Vec3::UnitY()));
}

TEST(UrdfReader, JointVariablesSizedByType) {
  const JointSpec joint = LoadUrdfOnly("pendulum.urdf").joints.at(0);
  EXPECT_EQ(joint.initial_position, std::vector<double>({0.0}));
  EXPECT_EQ(joint.initial_velocity, std::vector<double>({0.0}));
  EXPECT_EQ(joint.effects.size(), 1u);
}

TEST(UrdfReader, InertiaRotatedIntoLinkFrame) {
  // inertial frame yawed 90 deg: its x (moment 1) lies along link y, its y (moment 2) along link x
  const BodySpec arm1 = Body(LoadUrdfOnly("double_pendulum.urdf"), "arm1");
  EXPECT_LT((arm1.inertia_cm_B - Vec3(2.0, 1.0, 3.0).asDiagonal().toDenseMatrix()).norm(), kTolerance);
  EXPECT_TRUE(arm1.p_BoBcm_B.isApprox(Vec3(0.5, 0.0, 0.0)));
}

TEST(UrdfReader, MasslessFixedLinksBecomeFrames) {
  // 'base' (fixed to the world) joins the ground, 'tip' (fixed to arm2) is a frame of arm2
  const ModelSpec spec = LoadUrdfOnly("double_pendulum.urdf");
  ASSERT_EQ(spec.bodies.size(), 2u);
  EXPECT_EQ(spec.bodies[0].name, "arm1");
  EXPECT_EQ(spec.bodies[1].name, "arm2");
  ASSERT_EQ(spec.joints.size(), 2u);
  EXPECT_EQ(spec.joints[0].name, "B1");
  EXPECT_EQ(spec.joints[1].name, "B2");
}

TEST(UrdfReader, JointOnMasslessGroundLinkComposesOrigins) {
  const JointSpec b1 = Joint(LoadUrdfOnly("double_pendulum.urdf"), "B1");
  EXPECT_EQ(b1.parent, "");
  EXPECT_TRUE(b1.p_PJ.isApprox(Vec3(0.0, 0.0, 2.0)));  // mount 1 m + hinge 1 m
}

TEST(UrdfReader, DynamicsDampingBecomesDamper) {
  const ModelSpec spec = LoadUrdfOnly("double_pendulum.urdf");
  const JointSpec& b1 = Joint(spec, "B1");
  ASSERT_EQ(b1.effects[0].dampers.size(), 1u);
  EXPECT_EQ(b1.effects[0].dampers[0].coefficient, 0.5);
  EXPECT_TRUE(Joint(spec, "B2").effects[0].dampers.empty());
}

TEST(UrdfReader, DynamicsFrictionBecomesConstantBoundFriction) {
  const ModelSpec spec = LoadUrdfOnly("double_pendulum.urdf");
  const JointSpec& b1 = Joint(spec, "B1");
  ASSERT_EQ(b1.effects[0].frictions.size(), 1u);
  EXPECT_EQ(b1.effects[0].frictions[0].law, FrictionSpec::Law::kConstantTorque);
  EXPECT_EQ(b1.effects[0].frictions[0].torque, 0.1);
  EXPECT_TRUE(Joint(spec, "B2").effects[0].frictions.empty());
}

TEST(UrdfReader, LimitGivesStopPositions) {
  // the spec outlives the reference (a temporary's joint read after its end: AddressSanitizer)
  const ModelSpec spec = LoadUrdfOnly("double_pendulum.urdf");
  const JointSpec& b1 = Joint(spec, "B1");
  EXPECT_TRUE(b1.has_limits);
  EXPECT_EQ(b1.limit_lower, -3.0);
  EXPECT_EQ(b1.limit_upper, 3.0);
}

TEST(UrdfReader, JointTypesMapToSpecTypes) {
  const std::string urdf = test::WorldUrdf({"a", "b", "c", "d"}, R"(
    <joint name="j_rev" type="revolute"><parent link="world"/><child link="a"/><axis xyz="0 0 1"/>
      <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
    <joint name="j_pri" type="prismatic"><parent link="a"/><child link="b"/><axis xyz="1 0 0"/>
      <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
    <joint name="j_fix" type="fixed"><parent link="b"/><child link="c"/></joint>
    <joint name="j_pla" type="planar"><parent link="c"/><child link="d"/><axis xyz="0 0 1"/></joint>)");
  const ModelSpec spec = test::LoadInline(urdf, "");
  EXPECT_EQ(Joint(spec, "j_rev").type, JointType::kRevolute);
  EXPECT_EQ(Joint(spec, "j_pri").type, JointType::kPrismatic);
  EXPECT_EQ(Joint(spec, "j_fix").type, JointType::kFixed);
  EXPECT_EQ(Joint(spec, "j_pla").type, JointType::kPlanar);
  EXPECT_EQ(Joint(spec, "j_pla").effects.size(), 3u);
  EXPECT_TRUE(Joint(spec, "j_fix").effects.empty());
}

TEST(UrdfReader, PlanarNormalAlongXTakesYAsInPlaneAxis) {
  const std::string urdf = test::WorldUrdf({"a"}, R"(
    <joint name="p" type="planar"><parent link="world"/><child link="a"/><axis xyz="1 0 0"/></joint>)");
  EXPECT_TRUE(test::LoadInline(urdf, "").joints.at(0).axis2_J.isApprox(Vec3::UnitY()));
}

TEST(UrdfReader, RootWithInertiaIsFreeBody) {
  const std::string urdf = R"(<robot name="free">
    <link name="satellite"><inertial><mass value="3"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  </robot>)";
  const ModelSpec spec = test::LoadInline(urdf, "");
  ASSERT_EQ(spec.bodies.size(), 1u);
  EXPECT_EQ(spec.bodies[0].name, "satellite");
  EXPECT_TRUE(spec.joints.empty());
  EXPECT_TRUE(spec.bodies[0].p_WB.isZero());
  EXPECT_TRUE(spec.bodies[0].R_WB.isIdentity());
}

TEST(UrdfReader, FloatingJointChildIsFreeBodyAtItsOrigin) {
  const std::string urdf = test::WorldUrdf({"drone"}, R"(
    <joint name="float" type="floating"><parent link="world"/><child link="drone"/><origin xyz="1 2 3"/></joint>)");
  const ModelSpec spec = test::LoadInline(urdf, "");
  EXPECT_TRUE(spec.joints.empty());
  ASSERT_EQ(spec.bodies.size(), 1u);
  EXPECT_TRUE(spec.bodies[0].p_WB.isApprox(Vec3(1.0, 2.0, 3.0)));
}

}  // namespace urdf_reader_test
}  // namespace flexmbd
