#pragma once
/// @file
/// The bound on a dense eigen-analysis (solver.eigen.method: dense; docs/config.md "solver.eigen"): its
/// first-order form is a dense (2n)^2 matrix over the n kinematic unknowns, solved by a dense eigensolver whose
/// time grows as n^3. Above the bound a model asking for it is a ConfigError at build time, before the
/// solver tries to allocate it. And the sparse method's limit: shift-invert on the second-order form takes no
/// element states (aero inflow), which only the dense first-order solve (theory (E7)) takes.

#include "flexmbd/model/model.hpp"

namespace flexmbd {

/// Kinematic unknowns (node and joint-variable unknowns) above which `method: dense` is refused. At 5,000 the
/// first-order form and its complex eigenvectors alone take 2.4 GB, and the dense eigensolver, at 1.1 s for
/// the flexible antenna's 220 degrees of freedom here, about (5000 / 220)^3 x 1.1 s = 3.6 hours.
constexpr int kMaxDenseEigenUnknowns = 5000;

/// Throws ConfigError when the model asks for a dense eigen-analysis of more than kMaxDenseEigenUnknowns
/// kinematic unknowns, naming the field and what to use instead.
void CheckEigenSize(const Model& model);

/// Throws ConfigError when an eigen-analysis (analysis: eigen, or at_times of a dynamic run) asks for
/// `method: sparse` on a model with element states, naming the field, the first state and what to use instead.
void CheckSparseEigenStates(const Model& model);

}  // namespace flexmbd
