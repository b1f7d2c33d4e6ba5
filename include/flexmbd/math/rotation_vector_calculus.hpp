#pragma once
/// @file
/// The rotation-vector maps of so3.hpp at one rotation vector psi, with the derivatives of the tangent operator
/// that analytic tangents of beams need (docs/theory.md, (B10)). With K = Skew(psi), s = |psi|^2 and
/// f_n(s) = sum_k (-1)^k s^k / (2k + n)!:
///   Exp(psi) = I + f_1 K + f_2 K^2,   T(psi) = I - f_2 K + f_3 K^2,   T(psi)^-1 = I + K/2 + c K^2,
/// c = (f_3 - 2 f_4) / (2 f_2), and f_n' = (n f_{n+2} - f_{n+1}) / 2 (d/ds), free of cancellation at small angles.

#include "flexmbd/math/so3.hpp"

namespace flexmbd {

class RotationVectorCalculus {
 public:
  /// How much to prepare: Exp and T only; also T^-1 and DT; also D2T and the derivative of T^-1.
  enum class Level { kMaps, kFirst, kSecond };

  explicit RotationVectorCalculus(const Vec3& psi, Level level = Level::kSecond);

  const Vec3& psi() const { return psi_; }
  /// Exp(psi).
  const Mat3& exp() const { return exp_; }
  /// The right Jacobian T(psi): d Exp(psi) = Exp(psi) Skew(T(psi) d psi).
  const Mat3& tangent() const { return tangent_; }
  /// T(psi)^-1 (level kFirst or kSecond).
  const Mat3& inverse_tangent() const { return inverse_tangent_; }

  /// The derivative along d of the secant operator S(psi) = f_1 I + f_2 K of so3.hpp (level kFirst or kSecond).
  Mat3 SecantDerivative(const Vec3& d) const;
  /// DT[d]: the derivative of T along d (level kFirst or kSecond).
  Mat3 TangentDerivative(const Vec3& d) const;
  /// The matrix of d -> DT[d] w, the derivative of T(psi) w at fixed w (level kFirst or kSecond).
  Mat3 TangentDerivativeApplied(const Vec3& w) const;
  /// The same for T(psi)^T w = T(-psi) w: entry (i, j) is w . (DT[e_j] e_i) (level kFirst or kSecond).
  Mat3 TransposedTangentDerivativeApplied(const Vec3& w) const;
  /// D2T[d1, d2]: the second derivative of T (symmetric in d1, d2; level kSecond).
  Mat3 TangentSecondDerivative(const Vec3& d1, const Vec3& d2) const;
  /// The symmetric matrix B with d1^T B d2 = m . (D2T[d1, d2] v) (level kSecond): the second derivative
  /// contracted on both sides, without forming D2T.
  Mat3 TangentSecondDerivativeForm(const Vec3& m, const Vec3& v) const;
  /// The derivative of T^-1 along d (level kSecond).
  Mat3 InverseTangentDerivative(const Vec3& d) const;

 private:
  // The derivative of T(sign psi) w along psi, sign = +-1.
  Mat3 AppliedDerivative(const Vec3& w, double sign) const;

  Vec3 psi_;
  Mat3 K_, K2_;
  // T = I - a K + b K^2 and T^-1 = I + K/2 + c K^2; the suffixes _s, _ss are d/ds, d2/ds2.
  double a_ = 0, a_s_ = 0, a_ss_ = 0, b_ = 0, b_s_ = 0, b_ss_ = 0, c_ = 0, c_s_ = 0;
  Mat3 exp_, tangent_, inverse_tangent_;
};

}  // namespace flexmbd
