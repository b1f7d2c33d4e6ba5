#pragma once
// The energy books (docs/theory.md (T6)) of a row of the runner's CSV: energy now plus everything removed, less the
// energy of the first row, and the energy that passed through the books, to which the imbalance is compared.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../integration/helpers/csv_table.hpp"

namespace flexmbd {
namespace test {

struct CsvBooks {
  double imbalance = 0;   ///< E + dissipated + numerical - external - E_first [J]
  double throughput = 0;  ///< |E_first| + dissipated + numerical + |external| [J]
};

inline CsvBooks BooksAt(const CsvTable& table, const std::vector<double>& row) {
  auto at = [&](const char* column) { return row.at(table.Column(column)); };
  const double first = table.rows.front().at(table.Column("energy.total"));
  const double removed = at("energy.dissipated") + at("energy.numerical_dissipation");
  return {at("energy.total") + removed - at("energy.external_work") - first,
          std::abs(first) + removed + std::abs(at("energy.external_work"))};
}

/// The largest imbalance of the books over the rows, relative to the energy through them at each.
inline double WorstImbalance(const CsvTable& table) {
  double worst = 0;
  for (const std::vector<double>& row : table.rows) {
    const CsvBooks books = BooksAt(table, row);
    worst = std::max(worst, std::abs(books.imbalance) / books.throughput);
  }
  return worst;
}

/// The largest fall of `column` from one row to the next, the value before the first row taken as 0: 0 for a work
/// that never falls (D8, a friction's work booked row by row).
inline double LargestFall(const CsvTable& table, const std::string& column) {
  const size_t k = table.Column(column);
  double before = 0, fell = 0;
  for (const std::vector<double>& row : table.rows) {
    fell = std::max(fell, before - row.at(k));
    before = row.at(k);
  }
  return fell;
}

}  // namespace test
}  // namespace flexmbd
