// Relative motion of lower pairs (include/flexmbd/joints/joint_kinematics.hpp) against hand values, and the
// relative velocity against finite differences of the relative pose.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/joints/joint_kinematics.hpp"
#include "flexmbd/math/so3.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace joint_kinematics_test {

// Hand values use the same trigonometric functions: a few ulp of O(1) entries.
constexpr double kHandValue = 1.0e-14;
// Central differences with step 1e-6 along q + s qdot: truncation ~1e-12, round-off ~1e-16 / 1e-6 = 1e-10.
constexpr double kStep = 1.0e-6;
constexpr double kFiniteDifference = 1.0e-8;

Mat3 RotZ(double a) {
  Mat3 R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return R;
}

Mat3 RotX(double a) {
  Mat3 R;
  R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return R;
}

JointSpec Spec(JointType type, const Vec3& axis, const Vec3& axis2 = Vec3::UnitX(), double pitch = 0.0) {
  JointSpec spec;
  spec.name = JointTypeName(type);
  spec.type = type;
  spec.axis_J = axis;
  spec.axis2_J = axis2;
  spec.pitch = pitch;
  return spec;
}

struct Pose {
  Mat3 R;
  Vec3 p;
};

Pose PoseAt(const JointKinematics& k, const Eigen::VectorXd& q) {
  Pose pose;
  RelativePose(k, q, &pose.R, &pose.p);
  return pose;
}

Eigen::VectorXd Vector(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<int>(values.size()));
  int k = 0;
  for (double x : values) v[k++] = x;
  return v;
}

void ExpectPose(const JointSpec& spec, const Eigen::VectorXd& q, const Mat3& R, const Vec3& p) {
  const Pose pose = PoseAt(MakeJointKinematics(spec), q);
  EXPECT_LT((pose.R - R).cwiseAbs().maxCoeff(), kHandValue) << spec.name;
  EXPECT_LT((pose.p - p).cwiseAbs().maxCoeff(), kHandValue) << spec.name;
}

TEST(JointKinematics, VariableCountsFollowTheTheory) {
  // Reference: docs: revolute 1, prismatic 1, cylindrical 2, screw 1, planar 3, universal 2, spherical 0, fixed 0.
  EXPECT_EQ(MakeJointKinematics(Spec(JointType::kRevolute, Vec3::UnitZ())).num_variables, 1);
  EXPECT_EQ(MakeJointKinematics(Spec(JointType::kPrismatic, Vec3::UnitZ())).num_variables, 1);
  EXPECT_EQ(MakeJointKinematics(Spec(JointType::kCylindrical, Vec3::UnitZ())).num_variables, 2);
  EXPECT_EQ(MakeJointKinematics(Spec(JointType::kScrew, Vec3::UnitZ())).num_variables, 1);
  EXPECT_EQ(MakeJointKinematics(Spec(JointType::kPlanar, Vec3::UnitZ())).num_variables, 3);
  EXPECT_EQ(MakeJointKinematics(Spec(JointType::kUniversal, Vec3::UnitZ())).num_variables, 2);
  const JointKinematics spherical = MakeJointKinematics(Spec(JointType::kSpherical, Vec3::UnitZ()));
  EXPECT_EQ(spherical.num_variables, 0);
  EXPECT_FALSE(spherical.rotation_constrained);
  const JointKinematics fixed = MakeJointKinematics(Spec(JointType::kFixed, Vec3::UnitZ()));
  EXPECT_EQ(fixed.num_variables, 0);
  EXPECT_TRUE(fixed.rotation_constrained);
}

TEST(JointKinematics, RevolutePoseIsRotationAboutAxis) {
  // Reference: R = Rot(z, phi), p = 0; the axis is normalised first.
  ExpectPose(Spec(JointType::kRevolute, Vec3(0, 0, 3.0)), Vector({0.7}), RotZ(0.7), Vec3::Zero());
}

TEST(JointKinematics, PrismaticPoseIsTranslationAlongAxis) {
  // Reference: R = I, p = s a with a the normalised axis.
  ExpectPose(Spec(JointType::kPrismatic, Vec3(1, 1, 0)), Vector({0.3}), Mat3::Identity(),
             0.3 / std::sqrt(2.0) * Vec3(1, 1, 0));
}

TEST(JointKinematics, CylindricalPoseRotatesAndSlidesAlongAxis) {
  // Reference: R = Rot(x, phi), p = s x for variables (phi, s).
  ExpectPose(Spec(JointType::kCylindrical, Vec3::UnitX()), Vector({0.5, 0.2}), RotX(0.5), Vec3(0.2, 0, 0));
}

TEST(JointKinematics, ScrewTranslatesPitchPerTurn) {
  // Reference: s = pitch phi / (2 pi): one and a half turns of a 0.02 m/rev screw advance 0.03 m.
  ExpectPose(Spec(JointType::kScrew, Vec3::UnitZ(), Vec3::UnitX(), 0.02), Vector({3.0 * M_PI}), RotZ(3.0 * M_PI),
             Vec3(0, 0, 0.03));
  ExpectPose(Spec(JointType::kScrew, Vec3::UnitZ(), Vec3::UnitX(), 0.02), Vector({-0.5 * M_PI}), RotZ(-0.5 * M_PI),
             Vec3(0, 0, -0.005));
}

TEST(JointKinematics, PlanarPoseTranslatesInPlaneOfOrthogonalisedAxes) {
  // Reference: variables (phi, x, y): R = Rot(n, phi), p = x e_x + y (n x e_x), with e_x the given in-plane
  // axis made orthogonal to the normal n: normal z and axis2 (1, 0, 0.5) give e_x = x, n x e_x = y.
  ExpectPose(Spec(JointType::kPlanar, Vec3::UnitZ(), Vec3(1, 0, 0.5)), Vector({0.4, 0.25, -0.6}), RotZ(0.4),
             Vec3(0.25, -0.6, 0));
}

TEST(JointKinematics, UniversalPoseComposesRotations) {
  // Reference: R = Rot(a1, phi1) Rot(a2, phi2), the second axis made orthogonal to the first:
  // a1 = z, axis2 (1, 0, 0.3) -> a2 = x.
  ExpectPose(Spec(JointType::kUniversal, Vec3::UnitZ(), Vec3(1, 0, 0.3)), Vector({0.9, -0.35}), RotZ(0.9) * RotX(-0.35),
             Vec3::Zero());
}

TEST(JointKinematics, SphericalAndFixedHaveIdentityPose) {
  // Reference: no variables; the frames coincide in translation (and in rotation for fixed).
  ExpectPose(Spec(JointType::kSpherical, Vec3::UnitZ()), Eigen::VectorXd(0), Mat3::Identity(), Vec3::Zero());
  ExpectPose(Spec(JointType::kFixed, Vec3::UnitZ()), Eigen::VectorXd(0), Mat3::Identity(), Vec3::Zero());
}

TEST(JointKinematics, RelativeVelocityMatchesHandValues) {
  // Reference: universal w = a1 phi1' + Rot(a1, phi1) a2 phi2'; screw v = pitch/(2 pi) phi' a;
  // planar w = n phi', v = x' e_x + y' e_y.
  Vec3 w, v;
  const JointKinematics universal = MakeJointKinematics(Spec(JointType::kUniversal, Vec3::UnitZ(), Vec3::UnitX()));
  RelativeVelocity(universal, Vector({0.9, -0.35}), Vector({1.5, -2.0}), &w, &v);
  EXPECT_LT((w - (1.5 * Vec3::UnitZ() - 2.0 * RotZ(0.9) * Vec3::UnitX())).norm(), kHandValue);
  EXPECT_LT(v.norm(), kHandValue);

  const JointKinematics screw = MakeJointKinematics(Spec(JointType::kScrew, Vec3::UnitY(), Vec3::UnitX(), 0.05));
  RelativeVelocity(screw, Vector({1.0}), Vector({4.0}), &w, &v);
  EXPECT_LT((w - 4.0 * Vec3::UnitY()).norm(), kHandValue);
  EXPECT_LT((v - 0.05 / (2.0 * M_PI) * 4.0 * Vec3::UnitY()).norm(), kHandValue);

  const JointKinematics planar = MakeJointKinematics(Spec(JointType::kPlanar, Vec3::UnitZ(), Vec3::UnitX()));
  RelativeVelocity(planar, Vector({0.3, 1.0, 2.0}), Vector({0.7, -1.0, 0.5}), &w, &v);
  EXPECT_LT((w - 0.7 * Vec3::UnitZ()).norm(), kHandValue);
  EXPECT_LT((v - Vec3(-1.0, 0.5, 0.0)).norm(), kHandValue);
}

TEST(JointKinematics, RelativeVelocityIsDerivativeOfRelativePose) {
  // Reference: d/dt R(q(t)) = Skew(w) R and d/dt p(q(t)) = v, by central differences along q + s qdot,
  // for every joint type with skewed, unnormalised axes.
  test::Random random(31);
  const Vec3 axis = Vec3(0.3, -1.2, 0.8), axis2 = Vec3(1.0, 0.4, -0.2);
  for (JointType type : {JointType::kRevolute, JointType::kPrismatic, JointType::kCylindrical, JointType::kScrew,
                         JointType::kPlanar, JointType::kUniversal, JointType::kSpherical, JointType::kFixed}) {
    const JointKinematics k = MakeJointKinematics(Spec(type, axis, axis2, 0.1));
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::VectorXd q = random.VectorX(k.num_variables, 3.0);
      const Eigen::VectorXd qdot = random.VectorX(k.num_variables, 2.0);
      const Pose plus = PoseAt(k, q + kStep * qdot), minus = PoseAt(k, q - kStep * qdot), at = PoseAt(k, q);
      const Vec3 w_fd = Axial((plus.R - minus.R) / (2.0 * kStep) * at.R.transpose());
      const Vec3 v_fd = (plus.p - minus.p) / (2.0 * kStep);
      Vec3 w, v;
      RelativeVelocity(k, q, qdot, &w, &v);
      EXPECT_LT((w - w_fd).norm(), kFiniteDifference) << JointTypeName(type);
      EXPECT_LT((v - v_fd).norm(), kFiniteDifference) << JointTypeName(type);
    }
  }
}

TEST(JointKinematics, ZeroAxisIsAConfigError) {
  // Reference: the header: "Throws ConfigError on a zero axis"; also for a second axis parallel to the first.
  EXPECT_THROW(MakeJointKinematics(Spec(JointType::kRevolute, Vec3::Zero())), ConfigError);
  EXPECT_THROW(MakeJointKinematics(Spec(JointType::kUniversal, Vec3::UnitZ(), Vec3(0, 0, 2.0))), ConfigError);
  EXPECT_NO_THROW(MakeJointKinematics(Spec(JointType::kSpherical, Vec3::Zero())));
}

}  // namespace joint_kinematics_test
}  // namespace flexmbd
