#pragma once
/// @file
/// Rotation tools on SO(3) (docs/theory.md, section "Rotations"). Rotation vectors are never added to
/// rotations: a node's rotation is updated as R_f = R_i Exp(theta), theta in the body frame at the start.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "flexmbd/math/so3_generic.hpp"

namespace flexmbd {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Skew and Axial are defined here, inline: the beam kernel calls them a few hundred times per element and
// evaluation, and a call cost as much as the few operations inside.

/// Skew-symmetric matrix with Skew(a) b = a x b.
inline Mat3 Skew(const Vec3& a) { return so3::SkewOf<double>(a); }

/// Vector a with Skew(a) = (A - A^T) / 2.
inline Vec3 Axial(const Mat3& A) { return 0.5 * Vec3(A(2, 1) - A(1, 2), A(0, 2) - A(2, 0), A(1, 0) - A(0, 1)); }

/// Exponential map: rotation by |theta| about theta/|theta| (Rodrigues).
Mat3 Exp(const Vec3& theta);

/// Logarithm: the rotation vector of R, with |result| <= pi.
Vec3 Log(const Mat3& R);

/// Rotation by angle [rad] about a unit axis.
Mat3 AxisAngle(const Vec3& unit_axis, double angle);

/// Right Jacobian (tangent operator) T(theta): d Exp(theta) = Exp(theta) Skew(T(theta) d theta).
Mat3 RightJacobian(const Vec3& theta);

/// Secant operator S(theta) with Exp(theta) - I = Skew(theta) S(theta): exact for finite theta, so the
/// change of a body-fixed vector over a step is linear in theta: (Exp(theta) - I) d = -Skew(S d) theta.
Mat3 SecantOperator(const Vec3& theta);

/// Exp(theta), SecantOperator(theta) and RightJacobian(theta) together: what a node's step needs, with the
/// trigonometric ratios they share computed once (each equal to what its own function returns).
struct IncrementMaps {
  Mat3 exp, secant, right_jacobian;
};
IncrementMaps IncrementMapsOf(const Vec3& theta);

/// sin(x)/x with its series near zero.
double Sinc(double x);

}  // namespace flexmbd
