#include "node_run.hpp"

#include "bag_samples.hpp"
#include "node_process.hpp"
#include "runner.hpp"
#include "sample_recorder.hpp"
#include "temp_dir.hpp"

namespace flexmbd {
namespace test {
namespace {
// Bounds on start-up, a short run at full speed and shutdown on a loaded 2-core machine; met in a few seconds.
constexpr std::chrono::seconds kRunTimeout(60);
constexpr std::chrono::seconds kExitTimeout(20);
}  // namespace

NodeRun RecordNodeAndRunner(const NodeRunCase& run_case) {
  const TempDir dir(run_case.node_name);
  const std::string bag = dir.File("node.bag");
  std::vector<std::string> arguments{"_real_time_factor:=0.0", "_wait_for_subscribers:=1", "_keep_alive:=true"};
  if (run_case.record_bag) arguments.push_back("_bag:=" + bag);
  NodeRun run;
  {
    SampleRecorder recorder(run_case.node_name);
    NodeProcess node(run_case.node_name, arguments);
    run.reached_end = recorder.WaitUntil(run_case.reached_end, kRunTimeout);
    node.Interrupt();
    run.exit_status = node.WaitForExit(kExitTimeout);
    run.node_output = node.Output();
    run.topics = recorder.Snapshot();
  }
  if (run_case.record_bag) run.bag = ReadBagSamples(bag, run_case.node_name);
  const std::string csv = dir.File("runner.csv");
  if (RunRunner(run_case.urdf, run_case.config, "--csv " + csv) == 0) run.csv = ReadCsv(csv);
  return run;
}

}  // namespace test
}  // namespace flexmbd
