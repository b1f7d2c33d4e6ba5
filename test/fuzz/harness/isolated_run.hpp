#pragma once
/// @file
/// Runs one fuzz input in a forked child, so a crash, an abort or a hang ends the child, not the campaign.

#include <functional>

#include "load_and_step.hpp"

namespace flexmbd {
namespace fuzz {

enum class Termination {
  kReturned,  ///< the work returned; `result` holds what it returned
  kCrashed,   ///< killed by a signal other than the time limit's (segfault, abort from a failed check)
  kTimedOut,  ///< still running at the time limit (CPU time), or blocked past its wall-clock backstop
  kExited,    ///< ended without returning (exit() in a library, a sanitizer report): `exit_code`
};

struct IsolatedResult {
  Termination termination = Termination::kReturned;
  int signal = 0;     ///< kCrashed: the signal
  int exit_code = 0;  ///< kExited: the status
  TargetResult result;
};

struct IsolationLimits {
  /// CPU-time limit [s]: a campaign at low priority on a busy machine gets a fraction of a core, and a wall-clock
  /// limit then reported slow inputs as hangs. A child that blocks without using CPU ends at kWallClockFactor
  /// times it.
  unsigned seconds = 5;
  unsigned long memory_mib = 0;   ///< address-space limit [MiB]; 0 for none (sanitizer builds need none)
  bool quiet = true;              ///< the child's stdout and stderr to /dev/null (urdfdom logs its errors)
};

/// The wall-clock backstop of a child's time limit, in multiples of IsolationLimits::seconds.
constexpr unsigned kWallClockFactor = 30;

/// Forks, runs `work` in the child under `limits` and reports how the child ended.
IsolatedResult RunIsolated(const std::function<TargetResult()>& work, const IsolationLimits& limits);

/// In a child of RunIsolated: multiplies the time it has left (CPU time and the wall-clock backstop) by `factor`.
/// Elsewhere (a replay in-process) nothing.
void ExtendTimeLimit(unsigned factor);

/// In a child of RunIsolated: the CPU seconds it has left; 0 elsewhere.
double CpuSecondsLeft();

}  // namespace fuzz
}  // namespace flexmbd
