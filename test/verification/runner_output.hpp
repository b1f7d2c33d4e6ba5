#pragma once
// Runs the command-line runner (flexmbd_run) on YAML text and reads the tables it prints.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace flexmbd {
namespace test {

/// Runs flexmbd_run on a URDF of the source tree with the given YAML text; returns its output (stdout and
/// stderr), and expects it to exit with `exit_status`.
inline std::string RunnerOutput(const std::string& urdf, const std::string& yaml_text, const std::string& name,
                                int exit_status = 0) {
  const std::string yaml = testing::TempDir() + name + ".yaml";
  std::ofstream(yaml) << yaml_text;
  const std::string out = testing::TempDir() + name + ".txt";
  const std::string command = std::string(FLEXMBD_RUNNER) + " --urdf " + FLEXMBD_SOURCE_DIR + "/" + urdf +
                              " --config " + yaml + " > " + out + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream file(out);
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == exit_status) << text.str();
  return text.str();
}

/// The frequency [Hz] of mode `index` in a printed mode table, or NaN when the row is missing.
inline double TableFrequency(const std::string& table, int index) {
  char row[16];
  std::snprintf(row, sizeof(row), "\n%4d  ", index);
  const size_t at = table.find(row);
  double frequency = std::nan("");
  if (at != std::string::npos) std::sscanf(table.c_str() + at, " %*d %lf", &frequency);
  return frequency;
}

// The table prints 8 significant digits.
constexpr double kPrintedTolerance = 1.0e-7;

}  // namespace test
}  // namespace flexmbd
