#include "flexmbd/model/eigen_size.hpp"

#include <iomanip>
#include <sstream>

#include "flexmbd/common/error.hpp"

namespace flexmbd {

void CheckEigenSize(const Model& model) {
  const SolverSpec& solver = model.solver();
  const bool dense = solver.eigen.method == SolverSpec::EigenSettings::Method::kDense;
  if (solver.analysis != SolverSpec::Analysis::kEigen || !dense) return;
  const int kinematic = model.num_unknowns() - model.num_multipliers();
  if (kinematic <= kMaxDenseEigenUnknowns) return;
  std::ostringstream msg;
  msg << std::setprecision(2) << (model.source().empty() ? "" : model.source() + ": ")
      << "solver.eigen.method: dense for " << kinematic
      << " kinematic unknowns (node and joint-variable unknowns), more than " << kMaxDenseEigenUnknowns
      << ": its dense first-order form alone would take " << 8.0 * (2.0 * kinematic) * (2.0 * kinematic) / 1.0e9
      << " GB; expected method: sparse (the lowest modes by shift-invert) or auto";
  throw ConfigError(msg.str());
}

}  // namespace flexmbd
