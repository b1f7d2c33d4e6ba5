#pragma once
/// @file
/// The iteration matrix in compressed-column form with a pattern fixed at construction, a map from each
/// element's local entries to their positions (assembly does not allocate), and its KLU factorisation:
/// one symbolic analysis, then a numeric refactorisation per Newton iteration. The elements are evaluated on
/// solver.threads threads where that pays, with the results of one thread bit for bit (docs/theory.md, "Assembly
/// on several threads").

#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "flexmbd/elements/element.hpp"

namespace flexmbd {

class Model;
class ParallelAssembly;
struct ElementBlocks;

class SparseSystem {
 public:
  explicit SparseSystem(const Model& model);
  ~SparseSystem();
  SparseSystem(const SparseSystem&) = delete;
  SparseSystem& operator=(const SparseSystem&) = delete;

  /// Residual and per-row magnitude of its terms for the context; the tangent too when asked.
  void Assemble(const StepContext& ctx, bool with_tangent);

  const Eigen::VectorXd& residual() const { return residual_; }
  const Eigen::VectorXd& magnitude() const { return magnitude_; }
  /// Sum of |entries| of each row of the last assembled tangent: with the size of the unknowns it bounds the
  /// round-off of the residual.
  const Eigen::VectorXd& row_abs_sum() const { return row_abs_sum_; }

  /// Solves J dx = -residual, factorising the last assembled tangent first if `refactorise` (otherwise the
  /// previous factorisation is reused). Returns false if the matrix is singular.
  bool Solve(Eigen::VectorXd* dx, bool refactorise = true);

  int num_nonzeros() const { return static_cast<int>(values_.size()); }
  /// Threads that evaluated the elements in the last assembly: 1, or solver.threads once assemblies of that kind
  /// take long enough to pay for the hand-over.
  int assembly_threads() const { return assembly_threads_; }

  /// What the current factorisation was made for (a dynamic step size), so a caller can reuse it for the
  /// next solve of the same kind; NaN when it should not be reused. Set by the factorisation's user.
  double factorisation_key() const { return factorisation_key_; }
  void set_factorisation_key(double key) { factorisation_key_ = key; }
  bool has_factorisation() const;
  /// The unknown (column) whose pivot was zero in the last factorisation that failed as singular; -1 if none was
  /// found (the factorisation succeeded, or the solve was what failed).
  int singular_unknown() const;

  /// Time spent in assembly, factorisation and solve since construction [s].
  struct Timing {
    double assembly = 0, factorisation = 0, solve = 0;
  };
  const Timing& timing() const { return timing_; }

 private:
  bool Factorise();
  /// Adds one element's evaluated blocks to the residual, magnitudes and (with_tangent) the matrix values.
  void AddElement(int e, const ElementBlocks& blocks, bool with_tangent);

  const Model& model_;
  int n_;
  int threads_;  ///< solver.threads
  int assembly_threads_ = 1;
  std::vector<int> column_start_, row_index_;
  std::vector<double> values_;
  /// The rows scaled by their largest entry, as KLU's default scaling would (Factorise); KLU itself is told not to
  /// scale, which spares its checking pass over the matrix.
  std::vector<double> scaled_values_;
  Eigen::VectorXd row_scale_;      ///< largest |entry| of each row of the last assembled tangent (1 if none)
  Eigen::VectorXd factor_scale_;   ///< row_scale_ of the matrix the current factorisation was made from
  std::vector<std::vector<int>> scatter_;  ///< per element: position of local (i, j) at j * n_local + i (column order)
  Eigen::VectorXd residual_, magnitude_, row_abs_sum_;
  Eigen::VectorXd local_r_, local_m_;
  Eigen::MatrixXd local_J_;
  struct KluFactorisation;
  std::unique_ptr<KluFactorisation> klu_;
  std::unique_ptr<ParallelAssembly> parallel_;  ///< null with one thread
  Timing timing_;
  double factorisation_key_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace flexmbd
