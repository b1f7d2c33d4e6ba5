#pragma once
/// @file
/// Relative motion of a lower pair in terms of its explicit relative-motion variables q
/// (docs/theory.md, "Joints"). The child joint frame Jc relative to the parent joint frame Jp is
///   R_JpJc(q) = Rot(a_1, q_k1) Rot(a_2, q_k2) ...   (rotation factors, in order)
///   p_JpJc(q) = sum_k q_k c_k                        (linear in q)
/// Variables, in order: revolute (phi), prismatic (s), cylindrical (phi, s), screw (phi, with
/// s = pitch phi / 2 pi), planar (phi, x, y), universal (phi_1, phi_2), spherical and fixed (none).

#include <vector>

#include <Eigen/Core>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

/// One elementary rotation of R_JpJc: about `axis_J` (unit, in the frame it acts on) by q[variable].
struct RotationFactor {
  Vec3 axis_J;
  int variable;
};

/// The relative-motion description of one joint.
struct JointKinematics {
  int num_variables = 0;
  std::vector<RotationFactor> rotations;      ///< applied left to right
  std::vector<Vec3> translation_rates_Jp;     ///< c_k = d p_JpJc / d q_k, in Jp (size num_variables)
  bool rotation_constrained = true;           ///< false for a spherical joint
};

/// Builds the description from a spec. Axes are normalised; the universal joint's second axis and the
/// planar joint's in-plane x axis are made orthogonal to the first. Throws ConfigError on a zero axis.
JointKinematics MakeJointKinematics(const JointSpec& spec);

/// Relative pose of Jc in Jp for variables q (size num_variables).
void RelativePose(const JointKinematics& kinematics, const Eigen::VectorXd& q, Mat3* R_JpJc, Vec3* p_JpJc_Jp);

/// Relative angular and linear velocity of Jc in Jp, expressed in Jp, for variables q and rates qdot.
void RelativeVelocity(const JointKinematics& kinematics, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                      Vec3* w_JpJc_Jp, Vec3* v_JpJc_Jp);

}  // namespace flexmbd
