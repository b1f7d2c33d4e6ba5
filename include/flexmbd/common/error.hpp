#pragma once
/// @file
/// The kinds of error (DESIGN.md): bad input, numerical failure, an output file that cannot be written,
/// broken internal invariant.

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

/// An output file that cannot be written during a run (disk full, file size limit, I/O error); the run ends.
/// The message names the file, says why, and what the file holds.
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

namespace internal {
[[noreturn]] void AbortOnFailedDemand(const char* condition, const char* file, int line);
}  // namespace internal

}  // namespace flexmbd

/// Always-on internal invariant check: aborts with file and line. Never used for input validation.
#define FLEXMBD_DEMAND(condition) \
  ((condition) ? static_cast<void>(0) : ::flexmbd::internal::AbortOnFailedDemand(#condition, __FILE__, __LINE__))
