#pragma once
// One run of a case through the node (as fast as it goes, topics recorded) and through the runner (CSV), for
// tests that check the node's topics against expectations and against the runner's output of the same case.

#include <functional>
#include <string>

#include "csv_table.hpp"
#include "samples.hpp"

namespace flexmbd {
namespace test {

struct RecordedRun {
  bool reached_end = false;  ///< `reached` held before the timeout
  std::string node_output;
  Samples topics;
  CsvTable csv;              ///< empty if the runner failed
};

/// Starts the node `node_name` (its parameters come from the .test file), waits until `reached(topics)` holds,
/// stops the node with SIGINT, then runs the runner on `urdf` and `config` (paths relative to the repository).
RecordedRun RecordNodeAndRunner(const std::string& node_name, const std::string& urdf, const std::string& config,
                                const std::function<bool(const Samples&)>& reached);

}  // namespace test
}  // namespace flexmbd
