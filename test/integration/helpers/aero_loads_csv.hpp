#pragma once
// Compares ~aero_loads messages (from topics or a bag) with the aero.<section>.* and strip.<strip>.s<k>.* columns
// of a CSV written for the same run (include/flexmbd/io/csv_sink.hpp), sample by sample.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "csv_table.hpp"
#include "samples.hpp"

namespace flexmbd {
namespace test {

/// The loads and inflow states of a section or strip station entry under their CSV column suffixes
/// (docs/config.md, "aero" and output.strip_stations).
template <typename Entry>
std::vector<std::pair<std::string, double>> AeroColumns(const Entry& m) {
  std::vector<std::pair<std::string, double>> columns{
      {"lift", m.lift}, {"moment", m.moment}, {"hinge_moment", m.hinge_moment}};
  for (size_t k = 0; k < m.inflow.size(); ++k) columns.emplace_back("mu_" + std::to_string(k + 1), m.inflow[k]);
  return columns;
}

/// Expects one message per CSV row, at the row's time, each value of every section and strip station within
/// `relative_tolerance * (1 + |CSV value|)` of its column (the 1 covers values that are 0 in exact arithmetic).
inline void ExpectAeroLoadsMatchCsv(const std::vector<AeroLoadsArray>& messages, const CsvTable& csv,
                                    double relative_tolerance) {
  // Stamps are nanoseconds.
  constexpr double kStampResolution = 1.0e-9;
  ASSERT_EQ(messages.size(), csv.rows.size());
  const auto expect_columns = [&](const std::vector<double>& row, const std::string& prefix, const auto& entry) {
    for (const auto& [suffix, value] : AeroColumns(entry)) {
      const double expected = row[csv.Column(prefix + suffix)];
      EXPECT_NEAR(value, expected, relative_tolerance * (1.0 + std::abs(expected)))
          << prefix << suffix << " at t = " << row[0];
    }
  };
  for (size_t k = 0; k < messages.size(); ++k) {
    const std::vector<double>& row = csv.rows[k];
    EXPECT_NEAR(TimeOf(messages[k]), row[csv.Column("t")], kStampResolution) << "sample " << k;
    for (const AeroSectionLoads& section : messages[k].sections) {
      expect_columns(row, "aero." + section.section + ".", section);
    }
    for (const AeroStripStationLoads& station : messages[k].strip_stations) {
      expect_columns(row, "strip." + station.strip + ".s" + std::to_string(station.station) + ".", station);
    }
  }
}

}  // namespace test
}  // namespace flexmbd
