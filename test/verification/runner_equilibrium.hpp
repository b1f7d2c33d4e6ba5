#pragma once
// The static equilibrium the command-line runner finds for YAML text, read from the CSV it writes.

#include <string>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace test {

/// The last row of the CSV of a runner run on `yaml_text` (which must not give output.csv).
inline std::vector<double> EquilibriumRow(const std::string& urdf, std::string yaml_text, const std::string& name,
                                          CsvTable* csv) {
  const std::string path = testing::TempDir() + name + ".csv";
  yaml_text += "\noutput: {csv: " + path + "}\n";
  RunnerOutput(urdf, yaml_text, name);
  *csv = ReadCsv(path);
  return csv->rows.empty() ? std::vector<double>() : csv->rows.back();
}

}  // namespace test
}  // namespace flexmbd
