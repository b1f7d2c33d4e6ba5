#pragma once
// Internal pieces of the eigen-analysis shared by its source files (not part of the public interface).

#include <Eigen/Core>
#include <Eigen/QR>
#include <Eigen/SparseCore>
#include <complex>
#include <memory>
#include <vector>

#include "constraint_null_space.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"

namespace flexmbd {
namespace eigen_internal {

using ::flexmbd::ConstraintNullSpace;

/// W with W^T Mr W = I for the mass matrix Mr = Z^T M Z of the constrained motions. Throws SolverError if Mr
/// is not positive definite, naming the unknown that moves most in the motion without inertia.
Eigen::MatrixXd MassNormalisingBasis(const Model& model, const Eigen::MatrixXd& Mr, const Eigen::MatrixXd& Z);

/// Sparse LU by KLU (one analysis and factorisation) of a square matrix, for repeated solves.
class KluLu {
 public:
  KluLu();
  ~KluLu();
  KluLu(const KluLu&) = delete;
  KluLu& operator=(const KluLu&) = delete;
  /// Returns false if the matrix is singular.
  bool Factorise(const Eigen::SparseMatrix<double>& A);
  bool Factorise(const Eigen::SparseMatrix<std::complex<double>>& A);
  /// Solves A x = b in place with the last factorisation (of the same scalar type).
  bool Solve(Eigen::VectorXd* b) const;
  bool Solve(Eigen::VectorXcd* b) const;
  /// Reciprocal condition estimate of the last factorisation.
  double rcond() const;

  struct Data;

 private:
  std::unique_ptr<Data> data_;
};

/// One eigenvalue s of the first-order problem with its shape y in the coordinates of LinearisedSystem.
struct RawMode {
  std::complex<double> s;
  Eigen::VectorXcd x;
  double round_off = 0.0;  ///< the solver's round-off in s [1/s] (theory (E5)): growth up to it is not resolved
};

/// The largest rate of a state's motion [1/s]: node angular rates, node speeds over the model's length scale, joint
/// rates. The time scale of the second differences of (E2), and the scale of the stiffness its accelerations feed.
double ReferenceRate(const Model& model, const State& state);

/// Turns the eigenvalues of an analysis into modes (theory (E5)): one mode per conjugate pair (the root with
/// Im s > 0) and per real root. A root is rigid-body when |s| <= `limit` [1/s], the solver's round-off of a zero
/// root (the dense solvers': options.rigid_tolerance times `scale`, the model's frequency scale); when |s| is within
/// the resolution of the reference motion (a fraction of its largest rate, ReferenceRate); or when both |s| and the
/// stiffness and velocity terms its shape engages (|x|^T |K| |x| and |x|^T |D| |x| over x^H M x) are at round-off
/// level against scale. Each mode's growth_round_off is a margin times its root's round_off. Rigid roots
/// give one mode each in a symmetric problem (`symmetric`: one root omega^2 per degree of freedom), else half
/// as many, rounded up (a rigid motion is a double root of the first-order problem), with shapes spanning the
/// roots' vectors. Sorted rigid first, then by frequency, and cut to options.num_modes. The last `num_states`
/// components of each shape are element states: a root that moves them alone is never rigid.
void ClassifyModes(const Model& model, const LinearisedSystem& system, const std::vector<RawMode>& all, bool symmetric,
                   int num_states, double scale, double limit, const EigenOptions& options, EigenResult* result);

/// The rigid-body test of ClassifyModes for one root.
bool IsRigidRoot(const LinearisedSystem& system, const RawMode& mode, int num_states, double scale, double limit);

/// Every mode by null-space elimination and a dense eigensolver.
EigenResult SolveDense(const Model& model, const LinearisedSystem& system, const EigenOptions& options);

/// Every mode of a model with element states: the second-order motions reduced and mass-normalised as in
/// SolveDense, the element states as first-order rows, one dense generalized problem (theory (E7)).
EigenResult SolveDenseWithStates(const Model& model, const LinearisedSystem& system, const EigenOptions& options);

/// The lowest modes (or those near options.shift_hz) by shift-invert Arnoldi on the constrained quadratic
/// pencil (theory (E6)); by SolveDense when the Krylov space would span most of the constrained space.
EigenResult SolveSparse(const Model& model, const LinearisedSystem& system, const EigenOptions& options);

}  // namespace eigen_internal
}  // namespace flexmbd
