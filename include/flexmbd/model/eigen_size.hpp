#pragma once
/// @file
/// The bound on a dense eigen-analysis (solver.eigen.method: dense; docs/config.md "solver.eigen"): its
/// first-order form is a dense (2n)^2 matrix over the n kinematic unknowns, solved by a dense eigensolver whose
/// time grows as n^3. Above the bound a model asking for it is a ConfigError at build time, before the
/// solver tries to allocate it.

#include "flexmbd/model/model.hpp"

namespace flexmbd {

/// Kinematic unknowns (node and joint-variable unknowns) above which `method: dense` is refused. At 5,000 the
/// first-order form and its complex eigenvectors alone take 2.4 GB, and the dense eigensolver, at 1.1 s for
/// the flexible antenna's 220 degrees of freedom here, about (5000 / 220)^3 x 1.1 s = 3.6 hours.
constexpr int kMaxDenseEigenUnknowns = 5000;

/// Throws ConfigError when the model asks for a dense eigen-analysis of more than kMaxDenseEigenUnknowns
/// kinematic unknowns, naming the field and what to use instead.
void CheckEigenSize(const Model& model);

}  // namespace flexmbd
