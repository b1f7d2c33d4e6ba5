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
  kTimedOut,  ///< still running at the time limit
  kExited,    ///< ended without returning (exit() in a library, a sanitizer report): `exit_code`
};

struct IsolatedResult {
  Termination termination = Termination::kReturned;
  int signal = 0;     ///< kCrashed: the signal
  int exit_code = 0;  ///< kExited: the status
  TargetResult result;
};

struct IsolationLimits {
  unsigned seconds = 5;           ///< wall-clock limit (alarm) [s]
  unsigned long memory_mib = 0;   ///< address-space limit [MiB]; 0 for none (sanitizer builds need none)
  bool quiet = true;              ///< the child's stdout and stderr to /dev/null (urdfdom logs its errors)
};

/// Forks, runs `work` in the child under `limits` and reports how the child ended.
IsolatedResult RunIsolated(const std::function<TargetResult()>& work, const IsolationLimits& limits);

}  // namespace fuzz
}  // namespace flexmbd
