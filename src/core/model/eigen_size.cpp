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

void CheckSparseEigenStates(const Model& model) {
  const SolverSpec& solver = model.solver();
  const bool analysed = solver.analysis == SolverSpec::Analysis::kEigen || !solver.eigen.at_times.empty();
  if (!analysed || solver.eigen.method != SolverSpec::EigenSettings::Method::kSparse) return;
  if (model.num_element_states() == 0) return;
  throw ConfigError((model.source().empty() ? "" : model.source() + ": ") +
                    "solver.eigen.method: sparse cannot take the model's element states (" +
                    model.DescribeUnknown(model.element_state_unknown(0)) +
                    ", aero inflow); expected method: dense or auto (the dense first-order solve takes them)");
}

}  // namespace flexmbd
