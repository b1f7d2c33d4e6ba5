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
#include <vector>

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

/// The text of a file of the source tree ("test/data/yaml/stop_eigen.yaml"), to run or edit before running.
inline std::string SourceText(const std::string& relative) {
  std::ifstream file(std::string(FLEXMBD_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// Frequency [Hz], damping ratio and remark of row `index` of a printed mode table.
struct TableRow {
  double frequency_hz = std::nan(""), damping_ratio = std::nan("");
  std::string remark;
};

inline TableRow ModeRow(const std::string& table, int index) {
  char row[16];
  std::snprintf(row, sizeof(row), "\n%4d  ", index);
  TableRow out;
  const size_t at = table.find(row);
  if (at == std::string::npos) return out;
  const std::string line = table.substr(at + 1, table.find('\n', at + 1) - at - 1);
  std::istringstream values(line);
  int mode = 0;
  double damped = 0;
  values >> mode >> out.frequency_hz >> damped >> out.damping_ratio;
  std::getline(values >> std::ws, out.remark);
  return out;
}

/// The mode table the runner printed for the state at time `t` of a dynamic run (solver.eigen.at_times), from its
/// heading "eigen-analysis at t = <t> s" (t printed as %.6g) to the next line of the runner; "" if there is none.
inline std::string ModeTableAt(const std::string& output, double t) {
  char heading[64];
  std::snprintf(heading, sizeof(heading), "eigen-analysis at t = %.6g s", t);
  const size_t at = output.find(heading);
  if (at == std::string::npos) return "";
  return output.substr(at, output.find("\nflexmbd_run:", at) - at);
}

/// The frequency [Hz] of mode `index` in a printed mode table, or NaN when the row is missing.
inline double TableFrequency(const std::string& table, int index) { return ModeRow(table, index).frequency_hz; }

/// The frequencies [Hz] of the row of `factor` in a velocity_scale fan-plot table the runner printed (the columns
/// f1_Hz ...), empty if there is none.
inline std::vector<double> FanRow(const std::string& output, double factor) {
  const size_t table = output.find("velocity_scale f1_Hz");
  if (table == std::string::npos) return {};
  std::istringstream lines(output.substr(table));
  std::string header;
  std::getline(lines, header);
  size_t columns = 0;
  for (size_t at = header.find(" f"); at != std::string::npos; at = header.find(" f", at + 1)) ++columns;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream values(line);
    double parameter = 0;
    values >> parameter;
    if (parameter != factor) continue;
    std::vector<double> row(columns);
    for (double& f : row) values >> f;
    return row;
  }
  return {};
}

// The table prints 8 significant digits.
constexpr double kPrintedTolerance = 1.0e-7;

/// A change of stability an airspeed sweep reports: `flexmbd_run: <kind>: mode <k> at U = <speed> m/s (<f> Hz)`.
struct Crossing {
  std::string kind;  ///< flutter, divergence or stable again
  double speed = std::nan(""), frequency_hz = std::nan("");
};

/// Every change of stability in the runner's output, flutter lines first, then divergence, then stable again.
inline std::vector<Crossing> RunnerCrossings(const std::string& output) {
  std::vector<Crossing> crossings;
  for (const char* kind : {"flutter", "divergence", "stable again"}) {
    const std::string prefix = std::string("flexmbd_run: ") + kind + ": mode ";
    for (size_t at = output.find(prefix); at != std::string::npos; at = output.find(prefix, at + 1)) {
      Crossing c;
      c.kind = kind;
      int mode = 0;
      std::sscanf(output.c_str() + at + prefix.size(), "%d at U = %lf m/s (%lf Hz)", &mode, &c.speed, &c.frequency_hz);
      crossings.push_back(c);
    }
  }
  return crossings;
}

}  // namespace test
}  // namespace flexmbd
