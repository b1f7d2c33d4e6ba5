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
///
/// A path may also carry its exact variation along one increment (has_variation): the change of its start and
/// end values and of dg per unit of that increment, propagated by the product rule. Summed with the
/// multipliers, the variations of dg are the columns of the constraint forces' geometric stiffness
/// (docs/theory.md, "Geometric stiffness of constraints").

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "flexmbd/common/error.hpp"
#include "flexmbd/elements/element.hpp"

namespace flexmbd {

/// The increment a path's variation is taken along: local index `index` (-1: none). At the end configuration
/// (statics, end point) the start moves with the end, as the solver moves them.
struct PathDirection {
  int index = -1;
  bool at_end = false;
};

template <int Cols>
struct DiscretePath {
  using Value = Eigen::Matrix<double, 3, Cols>;
  static constexpr int kMaxIncrements = 16;  ///< two nodes (12) and up to three joint variables, plus room

  Value i = Value::Zero(), f = Value::Zero();
  std::array<Value, kMaxIncrements> dg, df;  ///< valid only where `active` has the bit set
  uint32_t active = 0;                       ///< bit k set: the path depends on increment k
  bool has_derivative = true;                ///< df is kept (false: only i, f and dg are)
  /// Variation along one increment (valid where has_variation; vdg where `active` has the bit set).
  Value vi = Value::Zero(), vf = Value::Zero();
  std::array<Value, kMaxIncrements> vdg;
  bool has_variation = false;

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
  /// Zero variation on every active increment (a path that does not move along the direction).
  void StartVariation() {
    if (has_variation) return;
    has_variation = true;
    vi.setZero();
    vf.setZero();
    for (uint32_t bits = active; bits != 0; bits &= bits - 1) vdg[__builtin_ctz(bits)].setZero();
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

/// Orientation R of a node whose increment theta sits at local indices offset..offset+2; with its variation
/// along `direction` if one is given.
MatrixPath NodeRotationPath(const NodeStep& node, int offset, const PathDirection& direction = {});

/// Position x of a node whose increment dx sits at local indices offset..offset+2.
VectorPath NodePositionPath(const NodeStep& node, int offset, const PathDirection& direction = {});

/// Rot(axis, q) for one joint variable q at local index `index`.
MatrixPath AxisRotationPath(const Vec3& unit_axis, double q_i, double q_f, int index,
                            const PathDirection& direction = {});

/// sum_k q_k c_k for joint variables at local indices offset + k.
VectorPath LinearPath(const std::vector<Vec3>& rates, const Eigen::Ref<const Eigen::VectorXd>& q_i,
                      const Eigen::Ref<const Eigen::VectorXd>& q_f, int offset, const PathDirection& direction = {});

/// a * b, or a^T * b when kTransposeA (without copying a transposed).
template <bool kTransposeA, int ColsB>
DiscretePath<ColsB> Multiply(const MatrixPath& a, const DiscretePath<ColsB>& b) {
  const auto A = [](const Mat3& m) -> Mat3 { return kTransposeA ? Mat3(m.transpose()) : m; };
  DiscretePath<ColsB> p;
  p.i = A(a.i) * b.i;
  p.f = A(a.f) * b.f;
  const Mat3 a_m = A(a.mid());
  const auto b_m = b.mid();
  p.active = a.active | b.active;
  p.has_derivative = a.has_derivative && b.has_derivative;
  for (uint32_t bits = p.active; bits != 0; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    if (a.depends_on(k) && b.depends_on(k)) {
      p.dg[k] = a_m * b.dg[k] + A(a.dg[k]) * b_m;
      if (p.has_derivative) p.df[k] = A(a.f) * b.df[k] + A(a.df[k]) * b.f;
    } else if (a.depends_on(k)) {
      p.dg[k] = A(a.dg[k]) * b_m;
      if (p.has_derivative) p.df[k] = A(a.df[k]) * b.f;
    } else {
      p.dg[k] = a_m * b.dg[k];
      if (p.has_derivative) p.df[k] = A(a.f) * b.df[k];
    }
  }
  if (!a.has_variation && !b.has_variation) return p;
  // The product rule on every term above; a factor without a variation does not move.
  p.has_variation = true;
  using ValueB = typename DiscretePath<ColsB>::Value;
  p.vi = (a.has_variation ? (A(a.vi) * b.i).eval() : ValueB::Zero().eval()) +
         (b.has_variation ? (A(a.i) * b.vi).eval() : ValueB::Zero().eval());
  p.vf = (a.has_variation ? (A(a.vf) * b.f).eval() : ValueB::Zero().eval()) +
         (b.has_variation ? (A(a.f) * b.vf).eval() : ValueB::Zero().eval());
  const Mat3 va_m = a.has_variation ? A(0.5 * (a.vi + a.vf)) : Mat3::Zero();
  const ValueB vb_m = b.has_variation ? ValueB(0.5 * (b.vi + b.vf)) : ValueB::Zero();
  for (uint32_t bits = p.active; bits != 0; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    ValueB& v = p.vdg[k];
    v.setZero();
    if (b.depends_on(k)) {
      if (a.has_variation) v.noalias() += va_m * b.dg[k];
      if (b.has_variation) v.noalias() += a_m * b.vdg[k];
    }
    if (a.depends_on(k)) {
      if (b.has_variation) v.noalias() += A(a.dg[k]) * vb_m;
      if (a.has_variation) v.noalias() += A(a.vdg[k]) * b_m;
    }
  }
  return p;
}

template <int ColsB>
DiscretePath<ColsB> operator*(const MatrixPath& a, const DiscretePath<ColsB>& b) {
  return Multiply<false>(a, b);
}

/// a^T * b.
template <int ColsB>
DiscretePath<ColsB> TransposeTimes(const MatrixPath& a, const DiscretePath<ColsB>& b) {
  return Multiply<true>(a, b);
}

/// a + sign * b.
template <int Cols>
DiscretePath<Cols> Combine(DiscretePath<Cols> a, const DiscretePath<Cols>& b, double sign) {
  a.i += sign * b.i;
  a.f += sign * b.f;
  a.has_derivative = a.has_derivative && b.has_derivative;
  const bool variation = a.has_variation || b.has_variation;
  if (variation) a.StartVariation();
  if (b.has_variation) {
    a.vi += sign * b.vi;
    a.vf += sign * b.vf;
  }
  for (uint32_t bits = b.active; bits != 0; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    if (a.depends_on(k)) {
      a.dg[k] += sign * b.dg[k];
      if (a.has_derivative) a.df[k] += sign * b.df[k];
      if (b.has_variation) a.vdg[k] += sign * b.vdg[k];
    } else {
      a.dg[k] = sign * b.dg[k];
      if (a.has_derivative) a.df[k] = sign * b.df[k];
      if (variation) a.vdg[k] = b.has_variation ? (sign * b.vdg[k]).eval() : DiscretePath<Cols>::Value::Zero().eval();
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
