#pragma once
/// @file
/// What the fuzzer runs on each input, in-process: the loader, the model builder and a few solver steps,
/// as flexmbd_run and the node would, with the run cut short.

#include <string>

#include "fuzz_input.hpp"

namespace flexmbd {
namespace fuzz {

/// The names the loader gives the inputs in its messages: the runner's files, or the node's parameters.
constexpr char kUrdfFileName[] = "fuzz_case.urdf";
constexpr char kYamlFileName[] = "fuzz_case.yaml";
constexpr char kUrdfParamName[] = "/robot_description";
constexpr char kParamNamespace[] = "/flexmbd_node";

/// A dynamic run ends after this many solver.dt (or at solver.t_end if sooner); BuildModel checks the output
/// bound against the t_end given.
constexpr int kStepsRun = 3;

enum class Outcome { kCompleted, kConfigError, kSolverError, kOtherException };

struct TargetResult {
  Outcome outcome = Outcome::kCompleted;
  std::string message;  ///< what() of the exception; for kOtherException prefixed with its type
};

/// Loads `input` through its channel, builds the model and runs it (static equilibrium, eigen-analysis, or
/// kStepsRun steps of a dynamic run), with no output files. Catches every exception.
TargetResult LoadAndStep(const FuzzInput& input);

}  // namespace fuzz
}  // namespace flexmbd
