#include "recorded_run.hpp"

#include <chrono>

#include "node_process.hpp"
#include "runner.hpp"
#include "sample_recorder.hpp"
#include "temp_dir.hpp"

namespace flexmbd {
namespace test {
namespace {
// Bounds on start-up, a short run at full speed and shutdown on a loaded 2-core machine.
constexpr std::chrono::seconds kRunTimeout(60), kExitTimeout(20);
}  // namespace

RecordedRun RecordNodeAndRunner(const std::string& node_name, const std::string& urdf, const std::string& config,
                                const std::function<bool(const Samples&)>& reached) {
  const TempDir dir("flexmbd_recorded_run");
  RecordedRun record;
  {
    SampleRecorder recorder(node_name);
    NodeProcess node(node_name, {"_real_time_factor:=0.0", "_wait_for_subscribers:=1", "_keep_alive:=true"});
    record.reached_end = recorder.WaitUntil(reached, kRunTimeout);
    node.Interrupt();
    node.WaitForExit(kExitTimeout);
    record.node_output = node.Output();
    record.topics = recorder.Snapshot();
  }
  const std::string csv = dir.File("runner.csv");
  if (RunRunner(urdf, config, "--csv " + csv) == 0) record.csv = ReadCsv(csv);
  return record;
}

}  // namespace test
}  // namespace flexmbd
