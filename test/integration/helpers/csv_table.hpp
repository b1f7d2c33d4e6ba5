#pragma once
// Reads a CSV written by CsvSink (include/flexmbd/io/csv_sink.hpp): a header row, then rows of numbers.

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace flexmbd {
namespace test {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  /// Index of the column `name`; throws if there is none.
  size_t Column(const std::string& name) const {
    const auto found = std::find(header.begin(), header.end(), name);
    if (found == header.end()) throw std::out_of_range("no CSV column '" + name + "'");
    return static_cast<size_t>(found - header.begin());
  }
};

inline CsvTable ReadCsv(const std::string& path) {
  CsvTable table;
  std::ifstream file(path);
  std::string line, cell;
  std::getline(file, line);
  for (std::istringstream cells(line); std::getline(cells, cell, ',');) table.header.push_back(cell);
  while (std::getline(file, line)) {
    std::vector<double>& row = table.rows.emplace_back();
    for (std::istringstream cells(line); std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
  }
  return table;
}

}  // namespace test
}  // namespace flexmbd
