#pragma once
/// @file
/// The fuzzer's oracle: every input completes, or ends in a ConfigError or SolverError with a one-line
/// message, and a ConfigError names the input it is about (a file, or the node's parameters).

#include <string>

#include "isolated_run.hpp"

namespace flexmbd {
namespace fuzz {

enum class Finding { kNone, kCrash, kHang, kWrongException, kBadMessage };

struct Verdict {
  Finding finding = Finding::kNone;
  std::string detail;  ///< what went wrong, one line; "" for kNone
};

Verdict Judge(const IsolatedResult& isolated);

/// "crash", "hang", "wrong_exception", "bad_message" (reproducer file names), "none".
const char* FindingName(Finding finding);

}  // namespace fuzz
}  // namespace flexmbd
