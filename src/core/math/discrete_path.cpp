#include "flexmbd/math/discrete_path.hpp"

#include <cmath>

#include "flexmbd/math/rotation_vector_calculus.hpp"

namespace flexmbd {
namespace {

// Whether local increment `index` is one of the `count` increments from `offset`; its position among them.
bool Along(const PathDirection& direction, int offset, int count, int* j) {
  *j = direction.index - offset;
  return direction.index >= 0 && *j >= 0 && *j < count;
}

// d/dx [sin(x)/x]: (x cos x - sin x)/x^2, by its series below 1e-2 (next term x^5/840 < 1e-12 relative).
double SincDerivative(double x) {
  if (std::abs(x) < 1.0e-2) return -x / 3.0 + x * x * x / 30.0;
  return (x * std::cos(x) - std::sin(x)) / (x * x);
}

}  // namespace

MatrixPath NodeRotationPath(const NodeStep& node, int offset, const PathDirection& direction) {
  MatrixPath p;
  p.i = node.R_i;
  p.f = node.R_f;
  // R_f - R_i = R_i Skew(theta) S(theta) = sum_j theta_j R_i Skew(e_j) S  (exact);  dR_f = R_f Skew(T dtheta).
  for (int j = 0; j < 3; ++j) {
    p.Set(offset + j, node.R_i * Skew(Vec3::Unit(j)) * node.S, node.R_f * Skew(node.T.col(j)));
  }
  int l = 0;
  if (!Along(direction, offset, 3, &l)) return p;
  p.StartVariation();
  p.vf = p.df[offset + l];
  if (direction.at_end) {
    // The node stands at R (theta = 0, S = I) and moves as R Exp(d): start and end together.
    p.vi = p.vf;
    for (int j = 0; j < 3; ++j) p.vdg[offset + j] = node.R_i * Skew(Vec3::Unit(l)) * Skew(Vec3::Unit(j));
    return p;
  }
  // S(theta) = f_1 I + f_2 Skew(theta) (docs/theory.md, (B10)) moves with theta_l.
  const RotationVectorCalculus c(node.theta, RotationVectorCalculus::Level::kFirst);
  const Mat3 dS = c.SecantDerivative(Vec3::Unit(l));
  for (int j = 0; j < 3; ++j) p.vdg[offset + j] = node.R_i * Skew(Vec3::Unit(j)) * dS;
  return p;
}

VectorPath NodePositionPath(const NodeStep& node, int offset, const PathDirection& direction) {
  VectorPath p;
  p.i = node.x_i;
  p.f = node.x_f;
  for (int j = 0; j < 3; ++j) p.Set(offset + j, Vec3::Unit(j), Vec3::Unit(j));
  int l = 0;
  if (!Along(direction, offset, 3, &l)) return p;
  p.StartVariation();
  p.vf = Vec3::Unit(l);
  if (direction.at_end) p.vi = p.vf;
  return p;
}

MatrixPath AxisRotationPath(const Vec3& unit_axis, double q_i, double q_f, int index, const PathDirection& direction) {
  MatrixPath p;
  p.i = AxisAngle(unit_axis, q_i);
  p.f = AxisAngle(unit_axis, q_f);
  // Rot(q_f) - Rot(q_i) = Rot(q_m) Skew(a) 2 sin(dq/2) = Rot(q_m) Skew(a) Sinc(dq/2) dq  (exact).
  const double dq = q_f - q_i;
  const Mat3 K = Skew(unit_axis);
  const Mat3 R_m = AxisAngle(unit_axis, 0.5 * (q_i + q_f));
  p.Set(index, R_m * K * Sinc(0.5 * dq), p.f * K);
  if (direction.index != index) return p;
  p.StartVariation();
  p.vf = p.f * K;
  if (direction.at_end) {
    // q_i and q_f move together: q_m moves, dq does not.
    p.vi = p.i * K;
    p.vdg[index] = R_m * K * K * Sinc(0.5 * dq);
  } else {
    p.vdg[index] = 0.5 * R_m * K * (K * Sinc(0.5 * dq) + Mat3::Identity() * SincDerivative(0.5 * dq));
  }
  return p;
}

VectorPath LinearPath(const std::vector<Vec3>& rates, const Eigen::Ref<const Eigen::VectorXd>& q_i,
                      const Eigen::Ref<const Eigen::VectorXd>& q_f, int offset, const PathDirection& direction) {
  VectorPath p;
  for (size_t k = 0; k < rates.size(); ++k) {
    if (rates[k].isZero()) continue;
    p.i += q_i[k] * rates[k];
    p.f += q_f[k] * rates[k];
    p.Set(offset + static_cast<int>(k), rates[k], rates[k]);
  }
  int l = 0;
  if (!Along(direction, offset, static_cast<int>(rates.size()), &l)) return p;
  p.StartVariation();
  p.vf = rates[l];
  if (direction.at_end) p.vi = p.vf;
  return p;
}

MatrixPath Transpose(MatrixPath a) {
  a.i.transposeInPlace();
  a.f.transposeInPlace();
  for (uint32_t bits = a.active; bits != 0; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    a.dg[k].transposeInPlace();
    if (a.has_derivative) a.df[k].transposeInPlace();
    if (a.has_variation) a.vdg[k].transposeInPlace();
  }
  if (a.has_variation) {
    a.vi.transposeInPlace();
    a.vf.transposeInPlace();
  }
  return a;
}

}  // namespace flexmbd
