#pragma once
// Hand-written ModelSpecs and trial points shared by the tangent and sparse-system unit tests.

#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "flexmbd/joints/joint_kinematics.hpp"
#include "flexmbd/math/so3.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/model/model_spec.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace test {

// A full, positive definite inertia tensor [kg m^2].
inline Mat3 SkewedInertia(double scale) {
  Mat3 I;
  I << 0.30, 0.02, -0.01, 0.02, 0.50, 0.03, -0.01, 0.03, 0.40;
  return scale * I;
}

inline BodySpec Body(const std::string& name, double mass, const Vec3& p_BoBcm_B) {
  BodySpec b;
  b.name = name;
  b.mass = mass;
  b.inertia_cm_B = SkewedInertia(mass);
  b.p_BoBcm_B = p_BoBcm_B;
  return b;
}

// A body of 2 kg with its centre of mass 0.6 m out along x and a full inertia tensor, on a pivot about y at the
// origin, under gravity along -z.
inline ModelSpec PivotedArm(const std::string& source) {
  ModelSpec spec;
  spec.source = source;
  spec.bodies.push_back(Body("link", 2.0, Vec3(0.6, 0.0, 0.0)));
  JointSpec pivot;
  pivot.name = "pivot";
  pivot.type = JointType::kRevolute;
  pivot.child = "link";
  pivot.axis_J = Vec3::UnitY();
  pivot.effects.resize(1);
  spec.joints.push_back(pivot);
  spec.solver.gravity = Vec3(0, 0, -9.81);
  return spec;
}

// Places `child` so that `joint` holds at its initial position, given the parent pose (identity for the world).
inline void PlaceChild(const Vec3& p_WP, const Mat3& R_WP, const JointSpec& joint, BodySpec* child) {
  const JointKinematics k = MakeJointKinematics(joint);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(k.num_variables);
  for (int i = 0; i < k.num_variables && i < static_cast<int>(joint.initial_position.size()); ++i) {
    q[i] = joint.initial_position[i];
  }
  Mat3 R_JpJc;
  Vec3 p_JpJc;
  RelativePose(k, q, &R_JpJc, &p_JpJc);
  const Mat3 R_WJp = R_WP * joint.R_PJ;
  const Vec3 p_WJp = p_WP + R_WP * joint.p_PJ;
  const Mat3 R_WJc = R_WJp * R_JpJc;
  const Vec3 p_WJc = p_WJp + R_WJp * p_JpJc;
  child->R_WB = R_WJc * joint.R_CJ.transpose();
  child->p_WB = p_WJc - child->R_WB * joint.p_CJ;
}

// A joint with skewed frames and axes on both sides.
inline JointSpec SkewedJoint(const std::string& name, JointType type, const std::string& parent,
                             const std::string& child) {
  JointSpec j;
  j.name = name;
  j.type = type;
  j.parent = parent;
  j.child = child;
  j.p_PJ = Vec3(0.1, -0.2, 0.3);
  j.R_PJ = Exp(Vec3(0.3, 0.2, -0.1));
  j.p_CJ = Vec3(-0.2, 0.05, 0.1);
  j.R_CJ = Exp(Vec3(-0.2, 0.4, 0.1));
  j.axis_J = Vec3(0.3, -1.2, 0.8);
  j.axis2_J = Vec3(1.0, 0.4, -0.2);
  j.pitch = 0.1;
  const std::vector<double> initial = {0.3, -0.2, 0.15};
  j.initial_position.assign(initial.begin(), initial.begin() + NumJointVariables(type));
  return j;
}

// One body on a revolute joint to the world with a spring, a damper and a cosine-ramp drive on its angle, and a
// ramped dead world force at an offset from the body origin.
inline ModelSpec WorldRevoluteModel() {
  ModelSpec spec;
  spec.source = "world revolute (unit test)";
  BodySpec link = Body("link", 2.0, Vec3(0.4, 0.1, -0.05));
  JointSpec hinge = SkewedJoint("hinge", JointType::kRevolute, "", "link");
  hinge.initial_position = {0.3};
  hinge.effects.resize(1);
  hinge.effects[0].springs.push_back({3.5, 0.1});
  hinge.effects[0].dampers.push_back({1.25});
  TimeFunctionSpec drive;
  drive.kind = TimeFunctionSpec::Kind::kCosineRamp;
  drive.offset = 0.3;
  drive.value = 0.8;
  drive.start = 0.0;
  drive.duration = 1.0;
  hinge.effects[0].drives.push_back(drive);
  PlaceChild(Vec3::Zero(), Mat3::Identity(), hinge, &link);
  LoadSpec load;
  load.body = "link";
  load.kind = LoadSpec::Kind::kForce;
  load.frame = LoadSpec::Frame::kWorld;
  load.vector = Vec3(1.0, -2.0, 3.0);
  load.p_BoP_B = Vec3(0.3, 0.2, 0.1);
  load.scale.kind = TimeFunctionSpec::Kind::kLinearRamp;
  load.scale.offset = 0.5;
  load.scale.value = 1.5;
  load.scale.duration = 2.0;
  spec.bodies.push_back(link);
  spec.joints.push_back(hinge);
  spec.loads.push_back(load);
  return spec;
}

// Two free bodies joined by one joint of the given type (or, with world_parent, one body on it to the world).
inline ModelSpec SingleJointModel(JointType type, bool world_parent) {
  ModelSpec spec;
  spec.source = std::string("single ") + JointTypeName(type) + " joint (unit test)";
  BodySpec a = Body("a", 1.5, Vec3(0.2, -0.1, 0.05));
  a.p_WB = Vec3(0.2, -0.1, 0.5);
  a.R_WB = Exp(Vec3(0.4, -0.3, 0.2));
  BodySpec b = Body("b", 0.8, Vec3(-0.1, 0.3, 0.2));
  JointSpec joint = SkewedJoint("j", type, world_parent ? "" : "a", "b");
  if (world_parent) {
    PlaceChild(Vec3::Zero(), Mat3::Identity(), joint, &b);
  } else {
    PlaceChild(a.p_WB, a.R_WB, joint, &b);
    spec.bodies.push_back(a);
  }
  spec.bodies.push_back(b);
  spec.joints.push_back(joint);
  return spec;
}

// One joint of each type, between two bodies or from the world to a body (test parameter).
struct JointCase {
  JointType type;
  bool world_parent;
};

inline std::vector<JointCase> AllJointCases() {
  std::vector<JointCase> cases;
  for (JointType type : {JointType::kRevolute, JointType::kPrismatic, JointType::kCylindrical, JointType::kScrew,
                         JointType::kPlanar, JointType::kSpherical, JointType::kUniversal, JointType::kFixed}) {
    cases.push_back({type, false});
    cases.push_back({type, true});
  }
  return cases;
}

inline std::string JointCaseName(const ::testing::TestParamInfo<JointCase>& info) {
  return std::string(JointTypeName(info.param.type)) + (info.param.world_parent ? "_to_world" : "_body_body");
}

inline void PrintTo(const JointCase& c, std::ostream* os) {
  *os << JointTypeName(c.type) << (c.world_parent ? " to world" : " body-body");
}

// A start state moved away from the (consistent) initial state: poses, velocities, previous-step accelerations,
// joint variables, rates and multipliers all random, at t = 0.3 s (inside the ramps).
inline State PerturbedState(const Model& model, Random* random) {
  State s = model.initial_state();
  s.t = 0.3;
  for (NodeState& n : s.nodes) {
    n.x += random->Vector(0.1);
    n.R = n.R * Exp(random->Vector(0.3));
    n.v = random->Vector(1.0);
    n.w = random->Vector(1.0);
    n.a_prev = random->Vector(5.0);
    n.alpha_prev = random->Vector(5.0);
  }
  for (int k = 0; k < s.q.size(); ++k) {
    s.q[k] += random->Uniform(-0.2, 0.2);
    s.qdot[k] = random->Uniform(-1.0, 1.0);
  }
  s.lambda = random->VectorX(model.num_multipliers(), 10.0);
  return s;
}

// Trial unknowns of one step: node increments, joint variable increments, multipliers.
inline Eigen::VectorXd RandomUnknowns(const Model& model, Random* random) {
  Eigen::VectorXd u(model.num_unknowns());
  for (int k = 0; k < model.num_nodes(); ++k) {
    u.segment<3>(model.node_unknown(k)) = random->Vector(0.05);
    u.segment<3>(model.node_unknown(k) + 3) = random->Vector(0.2);
  }
  for (int k = 0; k < model.num_variables(); ++k) u[model.variable_unknown(k)] = random->Uniform(-0.1, 0.1);
  for (int k = 0; k < model.num_multipliers(); ++k) u[model.multiplier_unknown(k)] = random->Uniform(-10.0, 10.0);
  return u;
}

}  // namespace test
}  // namespace flexmbd
