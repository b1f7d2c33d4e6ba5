#pragma once
/// @file
/// Exact discrete gradients of multilinear expressions over a step (docs/theory.md, "Discrete gradients").
/// A DiscretePath holds a 3x3 or 3x1 quantity at the start (i) and end (f) of a step, a discrete gradient
/// dg with  value_f - value_i = sum_k dg[k] xi_k  holding exactly for the step's increments xi, and the
/// derivative df[k] = d value_f / d xi_k. Products use the midpoint rule
///   (AB)_f - (AB)_i = A_m (B_f - B_i) + (A_f - A_i) B_m,   A_m = (A_i + A_f)/2,
/// which is exact, so constraint forces built from dg do exactly zero work when the constraint holds at i and f.
/// Only the increments a path depends on are stored (a bit set), so products of sparse paths stay cheap and
/// nothing is allocated on the heap. A path built from a factor without derivatives (has_derivative false)
/// keeps no df either: a residual needs only the values and dg, about half the work of each product.

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "flexmbd/common/error.hpp"
#include "flexmbd/elements/element.hpp"

namespace flexmbd {

template <int Cols>
struct DiscretePath {
  using Value = Eigen::Matrix<double, 3, Cols>;
  static constexpr int kMaxIncrements = 16;  ///< two nodes (12) and up to three joint variables, plus room

  Value i = Value::Zero(), f = Value::Zero();
  std::array<Value, kMaxIncrements> dg, df;  ///< valid only where `active` has the bit set
  uint32_t active = 0;                       ///< bit k set: the path depends on increment k
  bool has_derivative = true;                ///< df is kept (false: only i, f and dg are)

  bool depends_on(int k) const { return (active >> k) & 1u; }
  Value mid() const { return 0.5 * (i + f); }
  /// dg[k], or zero if the path does not depend on increment k.
  Value gradient(int k) const { return depends_on(k) ? dg[k] : Value::Zero(); }
  Value derivative(int k) const {
    FLEXMBD_DEMAND(has_derivative);
    return depends_on(k) ? df[k] : Value::Zero();
  }
  void Set(int k, const Value& gradient_k, const Value& derivative_k) {
    dg[k] = gradient_k;
    df[k] = derivative_k;
    active |= 1u << k;
  }
};
using MatrixPath = DiscretePath<3>;
using VectorPath = DiscretePath<1>;

/// A quantity that does not change over the step.
template <int Cols>
DiscretePath<Cols> ConstantPath(const typename DiscretePath<Cols>::Value& value) {
  DiscretePath<Cols> p;
  p.i = p.f = value;
  return p;
}

/// Orientation R of a node whose increment theta sits at local indices offset..offset+2.
MatrixPath NodeRotationPath(const NodeStep& node, int offset);

/// Position x of a node whose increment dx sits at local indices offset..offset+2.
VectorPath NodePositionPath(const NodeStep& node, int offset);

/// Rot(axis, q) for one joint variable q at local index `index`.
MatrixPath AxisRotationPath(const Vec3& unit_axis, double q_i, double q_f, int index);

/// sum_k q_k c_k for joint variables at local indices offset + k.
VectorPath LinearPath(const std::vector<Vec3>& rates, const Eigen::Ref<const Eigen::VectorXd>& q_i,
                      const Eigen::Ref<const Eigen::VectorXd>& q_f, int offset);

template <int ColsB>
DiscretePath<ColsB> operator*(const MatrixPath& a, const DiscretePath<ColsB>& b) {
  DiscretePath<ColsB> p;
  p.i = a.i * b.i;
  p.f = a.f * b.f;
  const Mat3 a_m = a.mid();
  const auto b_m = b.mid();
  p.active = a.active | b.active;
  p.has_derivative = a.has_derivative && b.has_derivative;
  for (uint32_t bits = p.active; bits != 0; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    if (a.depends_on(k) && b.depends_on(k)) {
      p.dg[k] = a_m * b.dg[k] + a.dg[k] * b_m;
      if (p.has_derivative) p.df[k] = a.f * b.df[k] + a.df[k] * b.f;
    } else if (a.depends_on(k)) {
      p.dg[k] = a.dg[k] * b_m;
      if (p.has_derivative) p.df[k] = a.df[k] * b.f;
    } else {
      p.dg[k] = a_m * b.dg[k];
      if (p.has_derivative) p.df[k] = a.f * b.df[k];
    }
  }
  return p;
}

/// a + sign * b.
template <int Cols>
DiscretePath<Cols> Combine(DiscretePath<Cols> a, const DiscretePath<Cols>& b, double sign) {
  a.i += sign * b.i;
  a.f += sign * b.f;
  a.has_derivative = a.has_derivative && b.has_derivative;
  for (uint32_t bits = b.active; bits != 0; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    if (a.depends_on(k)) {
      a.dg[k] += sign * b.dg[k];
      if (a.has_derivative) a.df[k] += sign * b.df[k];
    } else {
      a.dg[k] = sign * b.dg[k];
      if (a.has_derivative) a.df[k] = sign * b.df[k];
      a.active |= 1u << k;
    }
  }
  return a;
}

template <int Cols>
DiscretePath<Cols> operator+(const DiscretePath<Cols>& a, const DiscretePath<Cols>& b) {
  return Combine(a, b, 1.0);
}

template <int Cols>
DiscretePath<Cols> operator-(const DiscretePath<Cols>& a, const DiscretePath<Cols>& b) {
  return Combine(a, b, -1.0);
}

MatrixPath Transpose(MatrixPath a);

}  // namespace flexmbd
