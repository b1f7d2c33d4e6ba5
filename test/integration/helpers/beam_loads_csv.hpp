#pragma once
// Compares ~beam_loads messages (from topics or a bag) with the beam.<name>.s<k>.* columns of a CSV written for
// the same run (include/flexmbd/io/csv_sink.hpp), sample by sample.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "csv_table.hpp"
#include "samples.hpp"

namespace flexmbd {
namespace test {

/// The values of a station entry under their CSV column suffixes (docs/config.md, output.beam_stations).
inline std::vector<std::pair<std::string, double>> StationColumns(const BeamStationLoads& m) {
  return {{"N", m.N},   {"V2", m.V2}, {"V3", m.V3}, {"T", m.T},   {"M2", m.M2}, {"M3", m.M3},
          {"e1", m.e1}, {"g2", m.g2}, {"g3", m.g3}, {"k1", m.k1}, {"k2", m.k2}, {"k3", m.k3},
          {"ux", m.displacement.x}, {"uy", m.displacement.y}, {"uz", m.displacement.z},
          {"rx", m.rotation.x},     {"ry", m.rotation.y},     {"rz", m.rotation.z}};
}

/// Number of stations in the CSV: one `beam.<name>.s<k>.N` column each.
inline size_t CsvStationCount(const CsvTable& csv) {
  size_t count = 0;
  for (const std::string& column : csv.header) {
    const bool station_axial = column.rfind("beam.", 0) == 0 && column.size() > 2 &&
                               column.compare(column.size() - 2, 2, ".N") == 0;
    if (station_axial) ++count;
  }
  return count;
}

/// Expects one message per CSV row, at the row's time, with one entry per station of the CSV, each value within
/// `relative_tolerance * (1 + |CSV value|)` of its column (the 1 covers values that are 0 in exact arithmetic).
inline void ExpectBeamLoadsMatchCsv(const std::vector<BeamLoadsArray>& messages, const CsvTable& csv,
                                    double relative_tolerance) {
  // Stamps are nanoseconds.
  constexpr double kStampResolution = 1.0e-9;
  ASSERT_EQ(messages.size(), csv.rows.size());
  const size_t stations = CsvStationCount(csv);
  ASSERT_GT(stations, 0u) << "the CSV has no beam station columns";
  for (size_t k = 0; k < messages.size(); ++k) {
    const std::vector<double>& row = csv.rows[k];
    EXPECT_NEAR(TimeOf(messages[k]), row[csv.Column("t")], kStampResolution) << "sample " << k;
    ASSERT_EQ(messages[k].stations.size(), stations) << "sample " << k;
    for (const BeamStationLoads& station : messages[k].stations) {
      const std::string prefix = "beam." + station.beam + ".s" + std::to_string(station.station) + ".";
      for (const auto& [suffix, value] : StationColumns(station)) {
        const double expected = row[csv.Column(prefix + suffix)];
        EXPECT_NEAR(value, expected, relative_tolerance * (1.0 + std::abs(expected)))
            << prefix << suffix << " at t = " << row[0];
      }
    }
  }
}

}  // namespace test
}  // namespace flexmbd
