#pragma once
// Runs the command-line runner (flexmbd_run) from a test.

#include <sys/wait.h>

#include <cstdlib>
#include <string>

namespace flexmbd {
namespace test {

/// Absolute path of a file in the repository.
inline std::string SourcePath(const std::string& relative) { return std::string(FLEXMBD_SOURCE_DIR) + "/" + relative; }

/// Runs `flexmbd_run --urdf <urdf> --config <config> <arguments>` (paths relative to the repository) with its
/// output discarded; returns its exit status (-1 if it did not exit normally).
inline int RunRunner(const std::string& urdf, const std::string& config, const std::string& arguments) {
  const std::string command = std::string(FLEXMBD_RUNNER) + " --urdf " + SourcePath(urdf) + " --config " +
                              SourcePath(config) + " " + arguments + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace test
}  // namespace flexmbd
