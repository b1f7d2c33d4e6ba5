// Text tables of eigen-analysis results: modes of one analysis, and fan-plot tables of sweeps.

#include <algorithm>
#include <cstdio>
#include <string>

#include "flexmbd/solver/eigen_analysis.hpp"

namespace flexmbd {
namespace {

std::string Format(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

const char* Remark(const Mode& mode) {
  if (mode.rigid_body) return "rigid body";
  if (Unstable(mode)) return mode.damped_frequency_hz > 0 ? "unstable (flutter)" : "unstable (divergence)";
  if (mode.damped_frequency_hz == 0) return "overdamped (real root)";
  return "";
}

}  // namespace

// Growth within the solver's round-off in Re s is no instability (theory (E5)).
bool Unstable(const Mode& mode) { return !mode.rigid_body && mode.eigenvalue.real() > mode.growth_round_off; }

std::string FormatModeTable(const EigenResult& result) {
  std::string out = "mode  frequency_Hz    damped_Hz       damping_ratio   remark\n";
  for (size_t k = 0; k < result.modes.size(); ++k) {
    const Mode& m = result.modes[k];
    char line[160];
    std::snprintf(line, sizeof(line), "%4zu  %-14.8g  %-14.8g  %-14.6g  %s", k + 1, m.frequency_hz,
                  m.damped_frequency_hz, m.damping_ratio, Remark(m));
    std::string text = line;
    text.erase(text.find_last_not_of(' ') + 1);
    out += text + "\n";
  }
  return out;
}

std::string FormatFanPlot(const std::vector<SweepPoint>& points, const std::string& parameter_name, int num_modes,
                          char separator) {
  size_t columns = 0;
  for (const SweepPoint& p : points) columns = std::max(columns, p.result.modes.size());
  if (num_modes > 0) columns = std::min(columns, static_cast<size_t>(num_modes));
  std::string out = parameter_name;
  for (size_t k = 0; k < columns; ++k) out += separator + ("f" + std::to_string(k + 1) + "_Hz");
  for (size_t k = 0; k < columns; ++k) out += separator + ("zeta" + std::to_string(k + 1));
  out += "\n";
  for (const SweepPoint& p : points) {
    std::string line = Format("%.8g", p.parameter);
    const std::vector<Mode>& modes = p.result.modes;
    for (size_t k = 0; k < columns; ++k) {
      line += separator + (k < modes.size() ? Format("%.8g", modes[k].frequency_hz) : "nan");
    }
    for (size_t k = 0; k < columns; ++k) {
      line += separator + (k < modes.size() ? Format("%.6g", modes[k].damping_ratio) : "nan");
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace flexmbd
