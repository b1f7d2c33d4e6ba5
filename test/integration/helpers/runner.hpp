#pragma once
// Runs the command-line runner (flexmbd_run) from a test.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace flexmbd {
namespace test {

/// Absolute path of a file in the repository.
inline std::string SourcePath(const std::string& relative) { return std::string(FLEXMBD_SOURCE_DIR) + "/" + relative; }

/// Runs `flexmbd_run --urdf <urdf> --config <config> <arguments>` (paths relative to the repository) with its
/// output discarded, or its stderr kept in `errors` if given; returns its exit status (-1 if it did not exit
/// normally).
inline int RunRunner(const std::string& urdf, const std::string& config, const std::string& arguments,
                     std::string* errors = nullptr) {
  const std::string errors_path = testing::TempDir() + "runner_errors.txt";
  const std::string command = std::string(FLEXMBD_RUNNER) + " --urdf " + SourcePath(urdf) + " --config " +
                              SourcePath(config) + " " + arguments + " > /dev/null 2>" +
                              (errors ? errors_path : "&1");
  const int status = std::system(command.c_str());
  if (errors) {
    std::ifstream file(errors_path);
    std::ostringstream text;
    text << file.rdbuf();
    *errors = text.str();
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace test
}  // namespace flexmbd
