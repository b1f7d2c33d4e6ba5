#include "verdict.hpp"

#include <cstring>

namespace flexmbd {
namespace fuzz {
namespace {

// The YAML file's name can appear on the parameter channel too: its text is parsed before it becomes the tree
// (rosparam load); the loader sees only the parameter names there.
bool NamesInput(const std::string& message) {
  for (const char* name : {kUrdfFileName, kYamlFileName, kUrdfParamName, kParamNamespace}) {
    if (message.find(name) != std::string::npos) return true;
  }
  return false;
}

Verdict JudgeMessage(const TargetResult& result) {
  const std::string& message = result.message;
  if (message.empty()) return Verdict{Finding::kBadMessage, "an empty message"};
  if (message.find('\n') != std::string::npos) {
    return Verdict{Finding::kBadMessage, "a message of more than one line: " + message.substr(0, message.find('\n'))};
  }
  if (result.outcome == Outcome::kConfigError && !NamesInput(message)) {
    return Verdict{Finding::kBadMessage, "a ConfigError naming no input: " + message};
  }
  return Verdict{};
}

}  // namespace

Verdict Judge(const IsolatedResult& isolated) {
  switch (isolated.termination) {
    case Termination::kCrashed:
      return Verdict{Finding::kCrash, std::string("killed by signal ") + strsignal(isolated.signal)};
    case Termination::kTimedOut:
      return Verdict{Finding::kHang, "still running at the time limit"};
    case Termination::kExited:
      return Verdict{Finding::kCrash, "ended without a result, exit status " + std::to_string(isolated.exit_code)};
    case Termination::kReturned:
      break;
  }
  switch (isolated.result.outcome) {
    case Outcome::kCompleted:
      return Verdict{};
    case Outcome::kConfigError:
    case Outcome::kSolverError:
      return JudgeMessage(isolated.result);
    case Outcome::kOtherException:
      break;
  }
  return Verdict{Finding::kWrongException, isolated.result.message};
}

const char* FindingName(Finding finding) {
  switch (finding) {
    case Finding::kCrash:
      return "crash";
    case Finding::kHang:
      return "hang";
    case Finding::kWrongException:
      return "wrong_exception";
    case Finding::kBadMessage:
      return "bad_message";
    case Finding::kNone:
      break;
  }
  return "none";
}

}  // namespace fuzz
}  // namespace flexmbd
