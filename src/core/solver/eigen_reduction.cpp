// Mass normalisation of the constrained motions (docs/theory.md, eq. (E4)); the null space of B is
// constraint_null_space.cpp.

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

#include "dense_decompositions.hpp"
#include "eigen_internal.hpp"
#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace eigen_internal {
namespace {
// Smallest eigenvalue of the Jacobi-scaled reduced mass matrix (unit diagonal) accepted as positive: a motion
// without inertia gives round-off (1e-16); a genuine ill-conditioning of 1e10 is not a model we can analyse.
constexpr double kMassTolerance = 1.0e-10;
}  // namespace

Eigen::MatrixXd MassNormalisingBasis(const Model& model, const Eigen::MatrixXd& Mr, const Eigen::MatrixXd& Z) {
  const int r = static_cast<int>(Mr.rows());
  if (r == 0) return Eigen::MatrixXd(0, 0);
  const Eigen::MatrixXd symmetric = 0.5 * (Mr + Mr.transpose());
  auto fail = [&](const Eigen::VectorXd& reduced_motion, double ratio) {
    const Eigen::VectorXd motion = Z * reduced_motion;
    Eigen::Index worst = 0;
    motion.cwiseAbs().maxCoeff(&worst);
    std::ostringstream msg;
    msg << "eigen-analysis: the mass matrix of the constrained motions is not positive definite (smallest "
           "scaled eigenvalue "
        << ratio << "): a motion without inertia, moving mostly " << model.DescribeUnknown(static_cast<int>(worst))
        << "; give what it moves mass and inertia, or constrain it (joint variables have no inertia of their own)";
    throw SolverError(msg.str());
  };
  // Jacobi scaling makes the test independent of units (kg against kg m^2).
  Eigen::VectorXd scale(r);
  for (int i = 0; i < r; ++i) {
    if (!(symmetric(i, i) > 0.0)) fail(Eigen::VectorXd::Unit(r, i), symmetric(i, i));
    scale[i] = 1.0 / std::sqrt(symmetric(i, i));
  }
  const Eigen::MatrixXd scaled = scale.asDiagonal() * symmetric * scale.asDiagonal();
  const dense::SymmetricEigenpairs eig = dense::SymmetricEigen(scaled);
  const Eigen::VectorXd& values = eig.values;
  if (!(values[0] > kMassTolerance * values[r - 1])) {
    fail(scale.asDiagonal() * eig.vectors.col(0), values[0] / values[r - 1]);
  }
  return scale.asDiagonal() * eig.vectors * values.cwiseSqrt().cwiseInverse().asDiagonal();
}

}  // namespace eigen_internal
}  // namespace flexmbd
