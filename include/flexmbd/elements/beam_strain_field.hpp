#pragma once
/// @file
/// Section strains of one beam element at one configuration, and their first and second derivatives with
/// respect to the node perturbations p = (u_k, phi_k), nodes at x_k + u_k, R_k Exp(phi_k) (docs/theory.md,
/// (B10)-(B12)). Everything is fixed-size: no heap allocation.
///
/// The strains depend on the nodes only through the local coordinates z_k = (y_k, psi_k) of each node in the
/// frame of the reference node r, y_k = R_r^T (x_k - x_r), psi_k = Log(R_r^T R_k), and at Gauss point g only
/// through q_g = (y', psi, psi') interpolated from them. Derivatives are chained p -> z -> q -> strain.

#include <array>
#include <optional>

#include <Eigen/Core>

#include "flexmbd/elements/beam_shape.hpp"
#include "flexmbd/math/rotation_vector_calculus.hpp"

namespace flexmbd {

class BeamStrainField {
 public:
  static constexpr int kMaxNodes = BeamShape::kMaxNodes;
  static constexpr int kMaxPoints = BeamShape::kMaxPoints;
  static constexpr int kMaxDofs = 6 * kMaxNodes;
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  /// 6 x (6 nodes): a strain Jacobian.
  using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxDofs>;
  /// (6 nodes): forces or a direction in p.
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDofs, 1>;
  /// (6 nodes) x (6 nodes): a tangent.
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDofs, kMaxDofs>;
  /// Rows x (6 nodes), row-major when a single row (Eigen's rule for row vectors).
  template <int Rows, int MaxRows>
  using Wide = Eigen::Matrix<double, Rows, Eigen::Dynamic, Rows == 1 ? Eigen::RowMajor : Eigen::ColMajor, MaxRows,
                             kMaxDofs>;
  /// One value per Gauss point.
  using PointVectors = std::array<Vec6, kMaxPoints>;

  /// Node positions [m] and rotations of the element, in element order.
  struct Nodes {
    std::array<Vec3, kMaxNodes> x;
    std::array<Mat3, kMaxNodes> R;
  };

  /// How far to differentiate: strains only, first derivatives, or also second derivatives.
  enum class Order { kStrains, kFirst, kSecond };

  /// The chain rule from a configuration's perturbations to a step's increments: node k's perturbation is
  /// (translation_rate dx_k, rotation_k theta_k).
  struct IncrementMap {
    double translation_rate = 1.0;
    std::array<Mat3, kMaxNodes> rotation;

    /// Forces in the increments from forces in the perturbations: the map's transpose applied.
    Vector ApplyTransposed(int num_nodes, const Vector& f) const;
    /// M <- M times the map (on M's columns), in place, in fixed-size 3x3 strips.
    void ApplyToColumns(int num_nodes, Matrix* M) const;
  };

  BeamStrainField(const BeamShape& shape, const Nodes& nodes, Order order);

  int num_points() const { return shape_->num_points; }
  int num_dofs() const { return 6 * shape_->num_nodes(); }

  /// [eps; kappa] at point g (B2), section frame.
  const Vec6& strain(int g) const { return points_[g].strain; }
  /// The section frame R(s_g) = R_r Exp(psi_g) in W (B1).
  Mat3 SectionRotation(int g) const { return R_ref_ * points_[g].calculus->exp(); }

  /// B_g = d strain_g / dp (Order kFirst or kSecond).
  Jacobian StrainJacobian(int g) const;
  /// B_g v for every point g (Order kFirst or kSecond), without forming B_g.
  PointVectors StrainDirectionalDerivatives(const Vector& v) const;
  /// sum_g B_g^T stress_g: the generalised forces of section forces at the points (already weighted).
  Vector Gradient(const PointVectors& stress) const;
  /// K += sum_g B_g^T material_g B_g (if material) + d/dp [sum_g B_g^T stress_g] at fixed stress_g, rotations
  /// moved as R_k Exp(d phi_k) (Order kSecond).
  void AddTangent(const PointVectors& stress, const std::array<Mat6, kMaxPoints>* material, Matrix* K) const;
  /// sum_g B_g^T material_g B'_g, B' the strain Jacobians of `right`, a field of the same shape (Order kFirst
  /// or kSecond, both): the material tangent of stresses at one configuration that follow the strains of another.
  Matrix MaterialTangent(const BeamStrainField& right, const std::array<Mat6, kMaxPoints>& material) const;
  /// The tangent of a step whose stresses act at this configuration (the middle of the step) and follow the
  /// strains of `right` (its end), in the step's increments (Order kSecond here, kFirst or kSecond for right):
  ///   K += K_mat + (geometric ? K_geo : 0),  K_mat = sum_g B_g^T material_g B'_g M',
  /// K_geo = d/dp [sum_g B_g^T stress_g] M as AddTangent gives it without material, M and M' the maps of this
  /// configuration's and right's perturbations. Both share one pass of (dz/dp)^T on the left. Returns K_geo^T d,
  /// taken from vectors, so that leaving K_geo out saves its passes.
  Vector AddStepTangent(const PointVectors& stress, const BeamStrainField& right,
                        const std::array<Mat6, kMaxPoints>& material, const IncrementMap& map,
                        const IncrementMap& right_map, bool geometric, const Vector& d, Matrix* K) const;
  /// d/dp [B_g v] at fixed v, for every point g (Order kSecond). Note sum_g D_g^T s_g = K^T v for the K that
  /// AddTangent(s) adds without material: both are the second derivative of s . strain with the same turn.
  std::array<Jacobian, kMaxPoints> StrainJacobianDerivatives(const Vector& v) const;

 private:
  using Mat9 = Eigen::Matrix<double, 9, 9>;
  using Mat69 = Eigen::Matrix<double, 6, 9>;

  struct Point {
    Vec3 psi, dpsi, dy;  // psi_g, psi'_g, y'_g (local frame of the reference node)
    Vec3 a;              // Exp(psi)^T y' = eps + e1
    Vec6 strain;
    std::optional<RotationVectorCalculus> calculus;
    Mat69 E;             // d strain / d q
  };
  // What a pass of dz/dp on the right multiplies node k's 3x3 strips by: R_r^T on y_k (and its negative on the
  // reference's translation), Skew(y_k) and -T_k^-1 Q_k^T on the reference's rotation, T_k^-1 on phi_k; each
  // times an increment map's factor for the columns it lands in.
  struct NodePass {
    Mat3 translation, reference_y, reference_psi, rotation;
  };
  using Pass = std::array<NodePass, kMaxNodes>;

  struct Node {
    Vec3 y, psi;
    Mat3 skew_y;
    Mat3 Q;  // R_r^T R_k
    std::optional<RotationVectorCalculus> calculus;
    Mat3 inverse_tangent_Qt;  // T(psi_k)^-1 Q_k^T
  };

  // The right pass's factors multiplied by a map's.
  Pass PassOf(const IncrementMap& map) const;
  // c = sum_g (dq_g/dz)^T E_g^T stress_g, the forces in z; Kz = sum_g (dq_g/dz)^T [H_g + E_g^T material_g E_g]
  // (dq_g/dz), H_g the points' Hessians of stress . strain, if Kz is not null; Kz^T z_dot from vectors, without
  // forming Kz, if z_dot is not null.
  void LocalTangent(const PointVectors& stress, const std::array<Mat6, kMaxPoints>* material, Vector* c,
                    Matrix* Kz, const Vector* z_dot = nullptr, Vector* Kz_transposed_z_dot = nullptr) const;
  // Kz = sum_g (dq_g/dz)^T E_g^T material_g E'_g (dq_g/dz), E' of right.
  Matrix LocalMaterialTangent(const BeamStrainField& right, const std::array<Mat6, kMaxPoints>& material) const;
  // K += sum_k c_k . d2 z_k / dp2 and the turn of the forces (dz/dp)^T c along R_k Exp(phi_k) (B12).
  void AddCurvature(const Vector& c, Matrix* K) const;
  // sum_i stress_i d2 strain_i / dq2 (9 x 9).
  Mat9 PointHessian(const Point& p, const Vec6& stress) const;
  // d2 strain / dq2 along q_dot (6 x 9).
  Mat69 PointSecondDerivative(const Point& p, const Eigen::Matrix<double, 9, 1>& q_dot) const;
  // X dq_g/dz for X with 9 columns (rows x 6n), and (dq_g/dz)^T x for a 9-vector.
  template <int Rows>
  Wide<Rows, Rows> PointToLocal(int g, const Eigen::Matrix<double, Rows, 9>& X) const;
  // Kz += (dq_g/dz)^T H (dq_g/dz), leaving out the reference node's blocks (its z is zero).
  void AddPointToLocal(int g, const Mat9& H, Matrix* Kz) const;
  Vector PointToLocal(int g, const Eigen::Matrix<double, 9, 1>& x) const;
  // dz/dp applied: X (dz/dp) for X with 6n columns, and (dz/dp)^T c for a covector c of z.
  template <class Derived>
  Wide<Derived::RowsAtCompileTime, Derived::MaxRowsAtCompileTime>
  LocalToPerturbation(const Eigen::MatrixBase<Derived>& X) const;
  // X (dz/dp) M with the factors of PassOf(M); reference_rows_zero: X's rows of the reference node are zero, as
  // a Kz's are (its z is zero), and are skipped.
  template <class Derived>
  Wide<Derived::RowsAtCompileTime, Derived::MaxRowsAtCompileTime>
  LocalToPerturbation(const Eigen::MatrixBase<Derived>& X, const Pass& pass, bool reference_rows_zero = false) const;
  Vector LocalToPerturbation(const Vector& c) const;
  // (dz/dp)^T X for X with 6n rows.
  Matrix LocalToPerturbationRows(const Matrix& X) const;
  // dz/dp v.
  Vector LocalRate(const Vector& v) const;
  // dq_g/dz z_dot.
  Eigen::Matrix<double, 9, 1> PointRate(int g, const Vector& z_dot) const;
  // K += sum_k c_k . d2 z_k / dp2 for a covector c of z.
  void AddLocalCoordinateHessian(const Vector& c, Matrix* K) const;
  // d2 z / dp2 along v (6n x 6n).
  Matrix LocalCoordinateSecondDerivative(const Vector& v) const;

  const BeamShape* shape_;
  Mat3 R_ref_;
  std::array<Node, kMaxNodes> nodes_;
  std::array<Point, kMaxPoints> points_;
  Pass pass_;  // the right pass's factors without a map (Order kFirst or kSecond)
};

}  // namespace flexmbd
