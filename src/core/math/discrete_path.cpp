#include "flexmbd/math/discrete_path.hpp"

namespace flexmbd {

MatrixPath NodeRotationPath(const NodeStep& node, int offset) {
  MatrixPath p;
  p.i = node.R_i;
  p.f = node.R_f;
  // R_f - R_i = R_i Skew(theta) S(theta) = sum_j theta_j R_i Skew(e_j) S  (exact);  dR_f = R_f Skew(T dtheta).
  for (int j = 0; j < 3; ++j) p.Set(offset + j, node.R_i * Skew(Vec3::Unit(j)) * node.S, node.R_f * Skew(node.T.col(j)));
  return p;
}

VectorPath NodePositionPath(const NodeStep& node, int offset) {
  VectorPath p;
  p.i = node.x_i;
  p.f = node.x_f;
  for (int j = 0; j < 3; ++j) p.Set(offset + j, Vec3::Unit(j), Vec3::Unit(j));
  return p;
}

MatrixPath AxisRotationPath(const Vec3& unit_axis, double q_i, double q_f, int index) {
  MatrixPath p;
  p.i = AxisAngle(unit_axis, q_i);
  p.f = AxisAngle(unit_axis, q_f);
  // Rot(q_f) - Rot(q_i) = Rot(q_m) Skew(a) 2 sin(dq/2) = Rot(q_m) Skew(a) Sinc(dq/2) dq  (exact).
  const double dq = q_f - q_i;
  const Mat3 K = Skew(unit_axis);
  p.Set(index, AxisAngle(unit_axis, 0.5 * (q_i + q_f)) * K * Sinc(0.5 * dq), p.f * K);
  return p;
}

VectorPath LinearPath(const std::vector<Vec3>& rates, const Eigen::Ref<const Eigen::VectorXd>& q_i,
                      const Eigen::Ref<const Eigen::VectorXd>& q_f, int offset) {
  VectorPath p;
  for (size_t k = 0; k < rates.size(); ++k) {
    if (rates[k].isZero()) continue;
    p.i += q_i[k] * rates[k];
    p.f += q_f[k] * rates[k];
    p.Set(offset + static_cast<int>(k), rates[k], rates[k]);
  }
  return p;
}

MatrixPath Transpose(MatrixPath a) {
  a.i.transposeInPlace();
  a.f.transposeInPlace();
  for (uint32_t bits = a.active; bits != 0; bits &= bits - 1) {
    const int k = __builtin_ctz(bits);
    a.dg[k].transposeInPlace();
    if (a.has_derivative) a.df[k].transposeInPlace();
  }
  return a;
}

}  // namespace flexmbd
