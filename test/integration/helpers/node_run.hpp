#pragma once
// One run of the node on a case, recorded from its topics (and its bag), plus the runner's CSV of the same case:
// what the rostests that compare the node with the core and the runner share.

#include <functional>
#include <optional>
#include <string>

#include "csv_table.hpp"
#include "samples.hpp"

namespace flexmbd {
namespace test {

struct NodeRunCase {
  std::string node_name;  ///< the node's name; its parameters come from the .test file, under /<node_name>/
  std::string urdf;       ///< the same case for the runner: URDF and YAML, relative to the repository
  std::string config;
  bool record_bag = false;                          ///< the node also writes its bag (~bag), read into NodeRun::bag
  std::function<bool(const Samples&)> reached_end;  ///< true once the topics hold the run's last sample
};

struct NodeRun {
  bool reached_end = false;        ///< reached_end held before the run timed out
  std::optional<int> exit_status;  ///< after SIGINT; nullopt if the node did not exit in time
  std::string node_output;
  Samples topics;
  Samples bag;   ///< the node's bag, if record_bag
  CsvTable csv;  ///< the runner's CSV; empty if the runner failed
};

/// Starts the node with real_time_factor 0, wait_for_subscribers 1 and keep_alive once a SampleRecorder listens,
/// waits until `reached_end` holds, stops it with SIGINT, reads its bag, then runs the runner on the same case
/// with --csv.
NodeRun RecordNodeAndRunner(const NodeRunCase& run_case);

}  // namespace test
}  // namespace flexmbd
