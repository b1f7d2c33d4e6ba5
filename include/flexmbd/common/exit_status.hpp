#pragma once
/// @file
/// Exit statuses of the command-line runner and the node (README.md; docs/ros.md, "Ending"). Every failure
/// also prints one line saying what failed.

namespace flexmbd {

constexpr int kExitSuccess = 0;
constexpr int kExitUsage = 1;          ///< runner only: bad command-line arguments
constexpr int kExitBadInput = 2;       ///< a ConfigError: bad URDF, YAML, parameter or output path
constexpr int kExitRunFailed = 3;      ///< a SolverError, or an OutputError (an output file cannot be written)
constexpr int kExitInternalError = 4;  ///< an exception none of the above: a bug
constexpr int kExitInterrupted = 130;  ///< runner only: stopped by SIGINT or SIGTERM (the shell's 128 + SIGINT)

}  // namespace flexmbd
