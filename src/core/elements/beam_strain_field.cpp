#include "flexmbd/elements/beam_strain_field.hpp"

namespace flexmbd {
namespace {

// Block offsets of q = (y', psi, psi') and of a node's six entries (translation, then rotation).
constexpr int kDy = 0, kPsi = 3, kDpsi = 6;
constexpr int kRotation = 3;

Mat3 SymmetricPart(const Mat3& A) { return 0.5 * (A + A.transpose()); }

}  // namespace

BeamStrainField::BeamStrainField(const BeamShape& shape, const Nodes& nodes, Order order)
    : shape_(&shape) {
  const int n = shape.num_nodes(), r = shape.reference;
  using Level = RotationVectorCalculus::Level;
  const Level point_level = order == Order::kStrains ? Level::kMaps
                            : order == Order::kFirst ? Level::kFirst
                                                     : Level::kSecond;
  R_ref_ = nodes.R[r];
  for (int k = 0; k < n; ++k) {
    Node& node = nodes_[k];
    node.Q = R_ref_.transpose() * nodes.R[k];
    node.psi = k == r ? Vec3::Zero() : Log(node.Q);
    node.y = R_ref_.transpose() * (nodes.x[k] - nodes.x[r]);
    node.skew_y = Skew(node.y);
    // The reference node's z is zero whatever the nodes do: no pass or curvature reads its maps.
    if (order != Order::kStrains && k != r) {
      node.calculus.emplace(node.psi, order == Order::kFirst ? Level::kFirst : Level::kSecond);
    }
  }
  for (int g = 0; g < shape.num_points; ++g) {
    Point& p = points_[g];
    p.psi = p.dpsi = p.dy = Vec3::Zero();
    for (int k = 0; k < n; ++k) {
      p.psi += shape.N[g][k] * nodes_[k].psi;
      p.dpsi += shape.dNds[g][k] * nodes_[k].psi;
      p.dy += shape.dNds[g][k] * nodes_[k].y;
    }
    p.calculus.emplace(p.psi, point_level);
    const Mat3& T = p.calculus->tangent();
    p.a = p.calculus->exp().transpose() * p.dy;
    p.strain << p.a - Vec3::UnitX(), T * p.dpsi;
  }
  if (order == Order::kStrains) return;
  for (int k = 0; k < n; ++k) {
    if (k == r) continue;
    Node& node = nodes_[k];
    node.inverse_tangent_Qt = node.calculus->inverse_tangent() * node.Q.transpose();
    pass_[k] = {R_ref_.transpose(), node.skew_y, node.inverse_tangent_Qt, node.calculus->inverse_tangent()};
  }
  for (int g = 0; g < shape.num_points; ++g) {
    Point& p = points_[g];
    const RotationVectorCalculus& c = *p.calculus;
    p.E.setZero();
    p.E.block<3, 3>(0, kDy) = c.exp().transpose();
    p.E.block<3, 3>(0, kPsi) = Skew(p.a) * c.tangent();
    p.E.block<3, 3>(3, kPsi) = c.TangentDerivativeApplied(p.dpsi);
    p.E.block<3, 3>(3, kDpsi) = c.tangent();
  }
}

namespace {
// q_g = (y', psi, psi') = sum_k (N'_k y_k, N_k psi_k, N'_k psi_k): columns of z are sums of columns of q.
template <class Derived>
BeamStrainField::Wide<Derived::RowsAtCompileTime, Derived::MaxRowsAtCompileTime>
PointToLocalColumns(const BeamShape& shape, int g, const Eigen::MatrixBase<Derived>& X) {
  const int n = shape.num_nodes();
  BeamStrainField::Wide<Derived::RowsAtCompileTime, Derived::MaxRowsAtCompileTime> out(X.rows(), 6 * n);
  for (int k = 0; k < n; ++k) {
    const double N = shape.N[g][k], dN = shape.dNds[g][k];
    out.template middleCols<3>(6 * k) = dN * X.template middleCols<3>(kDy);
    out.template middleCols<3>(6 * k + kRotation) =
        N * X.template middleCols<3>(kPsi) + dN * X.template middleCols<3>(kDpsi);
  }
  return out;
}

}  // namespace

template <int Rows>
BeamStrainField::Wide<Rows, Rows> BeamStrainField::PointToLocal(
    int g, const Eigen::Matrix<double, Rows, 9>& X) const {
  return PointToLocalColumns(*shape_, g, X);
}

BeamStrainField::Vector BeamStrainField::PointToLocal(int g, const Eigen::Matrix<double, 9, 1>& x) const {
  return PointToLocalColumns(*shape_, g, x.transpose()).transpose();
}

template <class Derived>
BeamStrainField::Wide<Derived::RowsAtCompileTime, Derived::MaxRowsAtCompileTime>
BeamStrainField::LocalToPerturbation(const Eigen::MatrixBase<Derived>& X) const {
  return LocalToPerturbation(X, pass_);
}

template <class Derived>
BeamStrainField::Wide<Derived::RowsAtCompileTime, Derived::MaxRowsAtCompileTime>
BeamStrainField::LocalToPerturbation(const Eigen::MatrixBase<Derived>& X, const Pass& pass,
                                     bool reference_rows_zero) const {
  // Taken in strips of rows of fixed height, so that every product is a fixed-size 3-column one.
  constexpr int kStrip = Derived::RowsAtCompileTime == 1 ? 1 : 3;
  const int n = shape_->num_nodes(), r = shape_->reference;
  BeamStrainField::Wide<Derived::RowsAtCompileTime, Derived::MaxRowsAtCompileTime> out(X.rows(), 6 * n);
  // Every other node's columns are assigned below; only the reference's are sums.
  out.template middleCols<6>(6 * r).setZero();
  if (reference_rows_zero) out.middleRows(6 * r, 6).setZero();
  for (int i = 0; i < X.rows(); i += kStrip) {
    if (reference_rows_zero && i / 6 == r) continue;
    for (int k = 0; k < n; ++k) {
      if (k == r) continue;
      const NodePass& factors = pass[k];
      const Eigen::Matrix<double, kStrip, 3> Xy = X.template block<kStrip, 3>(i, 6 * k);
      const Eigen::Matrix<double, kStrip, 3> Xpsi = X.template block<kStrip, 3>(i, 6 * k + kRotation);
      const Eigen::Matrix<double, kStrip, 3> XyRt = Xy * factors.translation;
      out.template block<kStrip, 3>(i, 6 * k) = XyRt;
      out.template block<kStrip, 3>(i, 6 * r) -= XyRt;
      out.template block<kStrip, 3>(i, 6 * r + kRotation) += Xy * factors.reference_y - Xpsi * factors.reference_psi;
      out.template block<kStrip, 3>(i, 6 * k + kRotation) = Xpsi * factors.rotation;
    }
  }
  return out;
}

BeamStrainField::Pass BeamStrainField::PassOf(const IncrementMap& map) const {
  // Every node's translation has the same rate, so the reference's translation columns take the same factor.
  const int n = shape_->num_nodes(), r = shape_->reference;
  Pass mapped;
  for (int k = 0; k < n; ++k) {
    if (k == r) continue;
    const NodePass& factors = pass_[k];
    mapped[k] = {map.translation_rate * factors.translation, factors.reference_y * map.rotation[r],
                 factors.reference_psi * map.rotation[r], factors.rotation * map.rotation[k]};
  }
  return mapped;
}

BeamStrainField::Vector BeamStrainField::IncrementMap::ApplyTransposed(int num_nodes, const Vector& f) const {
  Vector out(6 * num_nodes);
  for (int k = 0; k < num_nodes; ++k) {
    out.segment<3>(6 * k) = translation_rate * f.segment<3>(6 * k);
    out.segment<3>(6 * k + kRotation).noalias() = rotation[k].transpose() * f.segment<3>(6 * k + kRotation);
  }
  return out;
}

void BeamStrainField::IncrementMap::ApplyToColumns(int num_nodes, Matrix* M) const {
  for (int k = 0; k < num_nodes; ++k) {
    M->middleCols(6 * k, 3) *= translation_rate;
    for (int i = 0; i < M->rows(); i += 3) {
      const Mat3 block = M->block<3, 3>(i, 6 * k + kRotation);
      M->block<3, 3>(i, 6 * k + kRotation).noalias() = block * rotation[k];
    }
  }
}

BeamStrainField::Vector BeamStrainField::LocalToPerturbation(const Vector& c) const {
  return LocalToPerturbation(c.transpose()).transpose();
}

BeamStrainField::Matrix BeamStrainField::LocalToPerturbationRows(const Matrix& X) const {
  // The transpose of LocalToPerturbation(X^T), in strips of three columns.
  const int n = shape_->num_nodes(), r = shape_->reference;
  Matrix out(6 * n, X.cols());
  out.middleRows<6>(6 * r).setZero();  // every other node's rows are assigned below
  for (int j = 0; j < X.cols(); j += 3) {
    for (int k = 0; k < n; ++k) {
      if (k == r) continue;
      const Node& node = nodes_[k];
      const Mat3 Xy = X.block<3, 3>(6 * k, j), Xpsi = X.block<3, 3>(6 * k + kRotation, j);
      const Mat3 RXy = R_ref_ * Xy;
      out.block<3, 3>(6 * k, j) = RXy;
      out.block<3, 3>(6 * r, j) -= RXy;
      out.block<3, 3>(6 * r + kRotation, j) -= node.skew_y * Xy + node.inverse_tangent_Qt.transpose() * Xpsi;
      out.block<3, 3>(6 * k + kRotation, j) = node.calculus->inverse_tangent().transpose() * Xpsi;
    }
  }
  return out;
}

BeamStrainField::Vector BeamStrainField::LocalRate(const Vector& v) const {
  const int n = shape_->num_nodes(), r = shape_->reference;
  Vector z = Vector::Zero(6 * n);
  const Vec3 u_r = v.segment<3>(6 * r), phi_r = v.segment<3>(6 * r + kRotation);
  for (int k = 0; k < n; ++k) {
    if (k == r) continue;
    const Node& node = nodes_[k];
    z.segment<3>(6 * k) = R_ref_.transpose() * (v.segment<3>(6 * k) - u_r) + node.y.cross(phi_r);
    z.segment<3>(6 * k + kRotation) =
        node.calculus->inverse_tangent() * v.segment<3>(6 * k + kRotation) - node.inverse_tangent_Qt * phi_r;
  }
  return z;
}

BeamStrainField::Jacobian BeamStrainField::StrainJacobian(int g) const {
  return LocalToPerturbation(PointToLocal<6>(g, points_[g].E));
}

Eigen::Matrix<double, 9, 1> BeamStrainField::PointRate(int g, const Vector& z_dot) const {
  Eigen::Matrix<double, 9, 1> q_dot = Eigen::Matrix<double, 9, 1>::Zero();
  for (int k = 0; k < shape_->num_nodes(); ++k) {
    q_dot.segment<3>(kDy) += shape_->dNds[g][k] * z_dot.segment<3>(6 * k);
    q_dot.segment<3>(kPsi) += shape_->N[g][k] * z_dot.segment<3>(6 * k + kRotation);
    q_dot.segment<3>(kDpsi) += shape_->dNds[g][k] * z_dot.segment<3>(6 * k + kRotation);
  }
  return q_dot;
}

BeamStrainField::PointVectors BeamStrainField::StrainDirectionalDerivatives(const Vector& v) const {
  const Vector z_dot = LocalRate(v);
  PointVectors rates;
  for (int g = 0; g < num_points(); ++g) rates[g] = points_[g].E * PointRate(g, z_dot);
  return rates;
}

BeamStrainField::Vector BeamStrainField::Gradient(const PointVectors& stress) const {
  Vector c = Vector::Zero(num_dofs());
  for (int g = 0; g < num_points(); ++g) c += PointToLocal(g, points_[g].E.transpose() * stress[g]);
  return LocalToPerturbation(c);
}

void BeamStrainField::LocalTangent(const PointVectors& stress, const std::array<Mat6, kMaxPoints>* material,
                                   Vector* c, Matrix* Kz, const Vector* z_dot, Vector* Kz_transposed_z_dot) const {
  c->setZero(num_dofs());
  if (Kz != nullptr) Kz->setZero(num_dofs(), num_dofs());
  if (z_dot != nullptr) Kz_transposed_z_dot->setZero(num_dofs());
  for (int g = 0; g < num_points(); ++g) {
    const Point& p = points_[g];
    *c += PointToLocal(g, p.E.transpose() * stress[g]);
    Mat9 H = PointHessian(p, stress[g]);
    if (material != nullptr) {
      const Mat69 CE = (*material)[g] * p.E;
      H.noalias() += p.E.transpose().lazyProduct(CE);
    }
    if (Kz != nullptr) AddPointToLocal(g, H, Kz);
    if (z_dot != nullptr) *Kz_transposed_z_dot += PointToLocal(g, H.transpose() * PointRate(g, *z_dot));
  }
}

void BeamStrainField::AddCurvature(const Vector& c, Matrix* K) const {
  AddLocalCoordinateHessian(c, K);
  // The forces are gradients along R_k Exp(phi_k); moving R_k by Exp(d) turns them by half the rotation:
  // d/dd [grad at R Exp(d)] = Hessian + Skew(forces_phi) / 2 (docs/theory.md, (B12)).
  const Vector f = LocalToPerturbation(c);
  for (int k = 0; k < shape_->num_nodes(); ++k) {
    K->block<3, 3>(6 * k + kRotation, 6 * k + kRotation) += 0.5 * Skew(f.segment<3>(6 * k + kRotation));
  }
}

void BeamStrainField::AddTangent(const PointVectors& stress, const std::array<Mat6, kMaxPoints>* material,
                                 Matrix* K) const {
  Matrix Kz;
  Vector c;
  LocalTangent(stress, material, &c, &Kz);
  *K += LocalToPerturbationRows(LocalToPerturbation(Kz, pass_, true));
  AddCurvature(c, K);
}

BeamStrainField::Matrix BeamStrainField::LocalMaterialTangent(const BeamStrainField& right,
                                                              const std::array<Mat6, kMaxPoints>& material) const {
  Matrix Kz = Matrix::Zero(num_dofs(), num_dofs());
  for (int g = 0; g < num_points(); ++g) {
    const Mat69 CE = material[g] * right.points_[g].E;
    const Mat9 H = points_[g].E.transpose().lazyProduct(CE);
    AddPointToLocal(g, H, &Kz);
  }
  return Kz;
}

BeamStrainField::Matrix BeamStrainField::MaterialTangent(const BeamStrainField& right,
                                                         const std::array<Mat6, kMaxPoints>& material) const {
  return LocalToPerturbationRows(right.LocalToPerturbation(LocalMaterialTangent(right, material), right.pass_, true));
}

BeamStrainField::Vector BeamStrainField::AddStepTangent(const PointVectors& stress, const BeamStrainField& right,
                                                        const std::array<Mat6, kMaxPoints>& material,
                                                        const IncrementMap& map, const IncrementMap& right_map,
                                                        bool geometric, const Vector& d, Matrix* K) const {
  const int n = shape_->num_nodes();
  // Kz is formed only for K_geo; K_geo^T d needs Kz^T (dz/dp) d alone, which vectors give.
  const Vector z_dot = LocalRate(d);
  Matrix Kz;
  Vector c, Kz_transposed_z_dot;
  LocalTangent(stress, nullptr, &c, geometric ? &Kz : nullptr, &z_dot, &Kz_transposed_z_dot);
  // Both parts in z on the left, in the increments on the right, then one pass of (dz/dp)^T.
  Matrix right_part =
      right.LocalToPerturbation(LocalMaterialTangent(right, material), right.PassOf(right_map), true);
  if (geometric) right_part += LocalToPerturbation(Kz, PassOf(map), true);
  *K += LocalToPerturbationRows(right_part);
  // K_geo = [(dz/dp)^T Kz (dz/dp) + curvature] M: its transpose applied to d from vectors and the curvature.
  Matrix curvature = Matrix::Zero(num_dofs(), num_dofs());
  AddCurvature(c, &curvature);
  Vector transposed_d = LocalToPerturbation(Kz_transposed_z_dot);
  transposed_d.noalias() += curvature.transpose() * d;
  if (geometric) {
    map.ApplyToColumns(n, &curvature);
    *K += curvature;
  }
  return map.ApplyTransposed(n, transposed_d);
}

void BeamStrainField::AddPointToLocal(int g, const Mat9& H, Matrix* Kz) const {
  // (dq_g/dz) is a scalar multiple of the identity per 3x3 block: node l's columns are N'_l on y', N_l on psi
  // and N'_l on psi'. The reference node's blocks are skipped: its z is zero whatever the nodes do.
  const int n = shape_->num_nodes(), r = shape_->reference;
  for (int l = 0; l < n; ++l) {
    if (l == r) continue;
    const double N_l = shape_->N[g][l], dN_l = shape_->dNds[g][l];
    Eigen::Matrix<double, 9, 6> HA;
    HA.leftCols<3>() = dN_l * H.middleCols<3>(kDy);
    HA.rightCols<3>() = N_l * H.middleCols<3>(kPsi) + dN_l * H.middleCols<3>(kDpsi);
    for (int k = 0; k < n; ++k) {
      if (k == r) continue;
      const double N_k = shape_->N[g][k], dN_k = shape_->dNds[g][k];
      Kz->block<3, 6>(6 * k, 6 * l) += dN_k * HA.middleRows<3>(kDy);
      Kz->block<3, 6>(6 * k + kRotation, 6 * l) += N_k * HA.middleRows<3>(kPsi) + dN_k * HA.middleRows<3>(kDpsi);
    }
  }
}

BeamStrainField::Mat9 BeamStrainField::PointHessian(const Point& p, const Vec6& stress) const {
  const RotationVectorCalculus& c = *p.calculus;
  const Mat3& T = c.tangent();
  const Vec3 force = stress.head<3>(), moment = stress.tail<3>();
  Mat9 H = Mat9::Zero();
  // eps = Exp(psi)^T y' - e1: d eps = Exp(psi)^T dy' + Skew(a) T dpsi.
  const Mat3 cross = -c.exp() * Skew(force) * T;
  H.block<3, 3>(kDy, kPsi) = cross;
  H.block<3, 3>(kPsi, kDy) = cross.transpose();
  Mat3 psi_psi = T.transpose() * (p.a * force.transpose() - force.dot(p.a) * Mat3::Identity()) * T;
  // Entry (i, j) of (n x a) . DT[e_j] e_i, the derivative of T^T (n x a).
  psi_psi += c.TransposedTangentDerivativeApplied(force.cross(p.a));
  // kappa = T(psi) psi'.
  psi_psi += c.TangentSecondDerivativeForm(moment, p.dpsi);
  H.block<3, 3>(kPsi, kPsi) = psi_psi;
  // Entry (i, j) is m . DT[e_i] e_j.
  H.block<3, 3>(kPsi, kDpsi) = c.TransposedTangentDerivativeApplied(moment).transpose();
  H.block<3, 3>(kDpsi, kPsi) = H.block<3, 3>(kPsi, kDpsi).transpose();
  return H;
}

BeamStrainField::Mat69 BeamStrainField::PointSecondDerivative(const Point& p,
                                                              const Eigen::Matrix<double, 9, 1>& q_dot) const {
  const RotationVectorCalculus& c = *p.calculus;
  const Mat3& T = c.tangent();
  const Vec3 dy_dot = q_dot.segment<3>(kDy), psi_dot = q_dot.segment<3>(kPsi), dpsi_dot = q_dot.segment<3>(kDpsi);
  const Mat3 DT_dot = c.TangentDerivative(psi_dot);
  Mat69 D = Mat69::Zero();
  const Vec3 a_dot = c.exp().transpose() * dy_dot + p.a.cross(T * psi_dot);
  D.block<3, 3>(0, kDy) = -Skew(T * psi_dot) * c.exp().transpose();
  D.block<3, 3>(0, kPsi) = Skew(a_dot) * T + Skew(p.a) * DT_dot;
  D.block<3, 3>(3, kPsi) = c.TangentDerivativeApplied(dpsi_dot);
  for (int j = 0; j < 3; ++j) D.block<3, 1>(3, kPsi + j) += c.TangentSecondDerivative(Vec3::Unit(j), psi_dot) * p.dpsi;
  D.block<3, 3>(3, kDpsi) = DT_dot;
  return D;
}

void BeamStrainField::AddLocalCoordinateHessian(const Vector& c, Matrix* K) const {
  const int n = shape_->num_nodes(), r = shape_->reference;
  const int ur = 6 * r, phr = 6 * r + kRotation;
  for (int k = 0; k < n; ++k) {
    if (k == r) continue;
    const Node& node = nodes_[k];
    const int uk = 6 * k, phk = 6 * k + kRotation;
    // y_k: second-order part -Skew(phi_r) R_r^T (u_k - u_r) + Skew(phi_r)^2 y_k / 2.
    const Vec3 a = c.segment<3>(uk);
    const Mat3 Sa = Skew(a) * R_ref_.transpose();
    K->block<3, 3>(phr, uk) += Sa;
    K->block<3, 3>(phr, ur) -= Sa;
    K->block<3, 3>(uk, phr) += Sa.transpose();
    K->block<3, 3>(ur, phr) -= Sa.transpose();
    K->block<3, 3>(phr, phr) += SymmetricPart(Skew(a) * node.skew_y);
    // psi_k = Log(Q Exp(b)), b = c + phi_k + c x phi_k / 2, c = -Q^T phi_r (docs/theory.md, (B11)).
    const Vec3 b = c.segment<3>(phk);
    const Mat3& Tinv = node.calculus->inverse_tangent();
    const Vec3 t = Tinv.transpose() * b;
    const Mat3 half_cross = 0.5 * node.Q * Skew(t);
    K->block<3, 3>(phr, phk) += half_cross;
    K->block<3, 3>(phk, phr) += half_cross.transpose();
    Mat3 S;
    for (int m = 0; m < 3; ++m) S.col(m) = node.calculus->InverseTangentDerivative(Vec3::Unit(m)).transpose() * b;
    S = S * Tinv;
    S -= 0.5 * Skew(t);
    K->block<3, 3>(phk, phk) += S;
    K->block<3, 3>(phk, phr) -= S * node.Q.transpose();
    K->block<3, 3>(phr, phk) -= node.Q * S;
    K->block<3, 3>(phr, phr) += node.Q * S * node.Q.transpose();
  }
}

BeamStrainField::Matrix BeamStrainField::LocalCoordinateSecondDerivative(const Vector& v) const {
  const int n = shape_->num_nodes(), r = shape_->reference;
  const int ur = 6 * r, phr = 6 * r + kRotation;
  Matrix D = Matrix::Zero(num_dofs(), num_dofs());
  const Vec3 phi_r = v.segment<3>(phr);
  for (int k = 0; k < n; ++k) {
    if (k == r) continue;
    const Node& node = nodes_[k];
    const int uk = 6 * k, phk = 6 * k + kRotation;
    const Mat3 turn = Skew(phi_r) * R_ref_.transpose();
    D.block<3, 3>(uk, uk) = -turn;
    D.block<3, 3>(uk, ur) = turn;
    D.block<3, 3>(uk, phr) = Skew(R_ref_.transpose() * (v.segment<3>(uk) - v.segment<3>(ur))) -
                             0.5 * (Skew(phi_r) * node.skew_y + Skew(phi_r.cross(node.y)));
    const Mat3& Tinv = node.calculus->inverse_tangent();
    const Vec3 phi_k = v.segment<3>(phk);
    const Vec3 c = -node.Q.transpose() * phi_r, beta = c + phi_k;
    Mat3 M;
    for (int m = 0; m < 3; ++m) M.col(m) = node.calculus->InverseTangentDerivative(Vec3::Unit(m)) * beta;
    M = M * Tinv + 0.5 * Tinv * Skew(beta);
    D.block<3, 3>(phk, phk) = 0.5 * Tinv * Skew(c) + M;
    D.block<3, 3>(phk, phr) = 0.5 * Tinv * Skew(phi_k) * node.Q.transpose() - M * node.Q.transpose();
  }
  return D;
}

std::array<BeamStrainField::Jacobian, BeamStrainField::kMaxPoints> BeamStrainField::StrainJacobianDerivatives(
    const Vector& v) const {
  const int n = shape_->num_nodes();
  const Vector z_dot = LocalRate(v);
  const Matrix z_second = LocalCoordinateSecondDerivative(v);
  std::array<Jacobian, kMaxPoints> D;
  for (int g = 0; g < num_points(); ++g) {
    const Point& p = points_[g];
    const Eigen::Matrix<double, 9, 1> q_dot = PointRate(g, z_dot);
    const Wide<6, 6> EA = PointToLocal<6>(g, p.E);
    D[g] = LocalToPerturbation(PointToLocal<6>(g, PointSecondDerivative(p, q_dot)));
    D[g].noalias() += EA * z_second;
    // B_g at R Exp(d) applied to v is B_g T(d)^-1 v = B_g (v - v x d / 2 + ...) per node: -B_phi Skew(v_phi) / 2.
    const Jacobian B = LocalToPerturbation(EA);
    for (int k = 0; k < n; ++k) {
      D[g].middleCols<3>(6 * k + kRotation).noalias() -=
          0.5 * B.middleCols<3>(6 * k + kRotation) * Skew(v.segment<3>(6 * k + kRotation));
    }
  }
  return D;
}

}  // namespace flexmbd
