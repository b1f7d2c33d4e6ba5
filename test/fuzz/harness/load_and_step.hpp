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

/// A run's cost grows with the model's unknowns (bench/README.md, fuzz campaigns: three steps of a panel with
/// friction took 18 s alone at 1,000 cubic elements, 144 s at 10,000), so the time limit a model gets is the
/// campaign's times one per this many unknowns...
constexpr int kUnknownsPerTimeLimit = 5000;
/// ...and a model beyond the linear range (10,000 cubic elements, about 180,000 unknowns) is built but not
/// run: its run takes minutes to an hour of the code smaller models exercise.
constexpr int kLargestRunModel = 200000;

/// How many times the campaign's time limit a model of `unknowns` gets (at least once).
unsigned TimeLimitFactor(int unknowns);

enum class Outcome { kCompleted, kConfigError, kSolverError, kOtherException };

struct TargetResult {
  Outcome outcome = Outcome::kCompleted;
  std::string message;  ///< what() of the exception; for kOtherException prefixed with its type
};

/// Loads `input` through its channel, builds the model and runs it (static equilibrium, eigen-analysis, or
/// kStepsRun steps of a dynamic run; not beyond kLargestRunModel unknowns), with no output files. Under a time
/// limit it extends the limit by TimeLimitFactor once the model is built. Catches every exception.
TargetResult LoadAndStep(const FuzzInput& input);

}  // namespace fuzz
}  // namespace flexmbd
