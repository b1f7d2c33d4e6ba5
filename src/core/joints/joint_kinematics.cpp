#include "flexmbd/joints/joint_kinematics.hpp"

#include <cmath>
#include <string>

#include "flexmbd/common/error.hpp"
#include "flexmbd/math/so3.hpp"

namespace flexmbd {
namespace {
// An axis shorter than this cannot be normalised meaningfully.
constexpr double kMinAxisNorm = 1.0e-9;

Vec3 UnitAxis(const Vec3& axis, const JointSpec& spec, const char* field) {
  if (axis.norm() < kMinAxisNorm) {
    throw ConfigError("joint '" + spec.name + "': " + field + " is zero; expected a non-zero 3-vector");
  }
  return axis.normalized();
}

// Component of `v` orthogonal to unit `n`, normalised.
Vec3 OrthogonalUnit(const Vec3& v, const Vec3& n, const JointSpec& spec, const char* field) {
  return UnitAxis(v - v.dot(n) * n, spec, field);
}
}  // namespace

JointKinematics MakeJointKinematics(const JointSpec& spec) {
  JointKinematics k;
  k.num_variables = NumJointVariables(spec.type);
  k.translation_rates_Jp.assign(k.num_variables, Vec3::Zero());
  const Vec3 a = spec.type == JointType::kSpherical || spec.type == JointType::kFixed
                     ? Vec3::UnitZ()
                     : UnitAxis(spec.axis_J, spec, "axis");
  switch (spec.type) {
    case JointType::kRevolute:
      k.rotations = {{a, 0}};
      break;
    case JointType::kPrismatic:
      k.translation_rates_Jp[0] = a;
      break;
    case JointType::kCylindrical:
      k.rotations = {{a, 0}};
      k.translation_rates_Jp[1] = a;
      break;
    case JointType::kScrew:
      k.rotations = {{a, 0}};
      k.translation_rates_Jp[0] = spec.pitch / (2.0 * M_PI) * a;
      break;
    case JointType::kPlanar: {
      const Vec3 x = OrthogonalUnit(spec.axis2_J, a, spec, "axis2 (in-plane x axis)");
      k.rotations = {{a, 0}};
      k.translation_rates_Jp[1] = x;
      k.translation_rates_Jp[2] = a.cross(x);
      break;
    }
    case JointType::kUniversal:
      k.rotations = {{a, 0}, {OrthogonalUnit(spec.axis2_J, a, spec, "axis2"), 1}};
      break;
    case JointType::kSpherical:
      k.rotation_constrained = false;
      break;
    case JointType::kFixed:
      break;
  }
  return k;
}

void RelativePose(const JointKinematics& kinematics, const Eigen::VectorXd& q, Mat3* R_JpJc, Vec3* p_JpJc_Jp) {
  FLEXMBD_DEMAND(q.size() == kinematics.num_variables);
  Mat3 R = Mat3::Identity();
  for (const RotationFactor& factor : kinematics.rotations) R = R * AxisAngle(factor.axis_J, q[factor.variable]);
  Vec3 p = Vec3::Zero();
  for (int k = 0; k < kinematics.num_variables; ++k) p += q[k] * kinematics.translation_rates_Jp[k];
  *R_JpJc = R;
  *p_JpJc_Jp = p;
}

void RelativeVelocity(const JointKinematics& kinematics, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                      Vec3* w_JpJc_Jp, Vec3* v_JpJc_Jp) {
  FLEXMBD_DEMAND(q.size() == kinematics.num_variables && qdot.size() == kinematics.num_variables);
  Mat3 R = Mat3::Identity();
  Vec3 w = Vec3::Zero();
  for (const RotationFactor& factor : kinematics.rotations) {
    w += R * factor.axis_J * qdot[factor.variable];
    R = R * AxisAngle(factor.axis_J, q[factor.variable]);
  }
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < kinematics.num_variables; ++k) v += qdot[k] * kinematics.translation_rates_Jp[k];
  *w_JpJc_Jp = w;
  *v_JpJc_Jp = v;
}

}  // namespace flexmbd
