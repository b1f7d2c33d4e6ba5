#pragma once
/// @file
/// The three kinds of error (DESIGN.md): bad input, numerical failure, broken internal invariant.

#include <stdexcept>
#include <string>

namespace flexmbd {

/// Bad input: thrown at load or model-build time. The message names the file, the field path, the
/// offending value and the expected form.
class ConfigError : public std::runtime_error {
 public:
  explicit ConfigError(const std::string& message) : std::runtime_error(message) {}
};

/// A run that cannot go on (step below dt_min, singular system). The message carries time, step size and
/// the worst residual named by its unknown.
class SolverError : public std::runtime_error {
 public:
  explicit SolverError(const std::string& message) : std::runtime_error(message) {}
};

namespace internal {
[[noreturn]] void AbortOnFailedDemand(const char* condition, const char* file, int line);
}  // namespace internal

}  // namespace flexmbd

/// Always-on internal invariant check: aborts with file and line. Never used for input validation.
#define FLEXMBD_DEMAND(condition) \
  ((condition) ? static_cast<void>(0) : ::flexmbd::internal::AbortOnFailedDemand(#condition, __FILE__, __LINE__))
