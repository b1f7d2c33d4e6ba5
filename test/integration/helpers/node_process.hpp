#pragma once
// Runs flexmbd_node as a child process of a test, so that the test controls its start, signals and exit and
// reads its output. Its parameters come from the .test file (under /<name>/) and from `_param:=value`
// arguments.

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace flexmbd {
namespace test {

class NodeProcess {
 public:
  /// Starts `flexmbd_node __name:=<name> <arguments...>` with stdout and stderr sent to a file.
  NodeProcess(const std::string& name, const std::vector<std::string>& arguments);
  /// Kills the node if it still runs.
  ~NodeProcess();
  NodeProcess(const NodeProcess&) = delete;
  NodeProcess& operator=(const NodeProcess&) = delete;

  /// Sends SIGINT (what roslaunch and Ctrl-C send).
  void Interrupt();

  /// The exit status once the node has exited, or nullopt if it still runs after `timeout` (or was killed by
  /// a signal).
  std::optional<int> WaitForExit(std::chrono::milliseconds timeout);

  /// Everything the node wrote to stdout and stderr so far.
  std::string Output() const;

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  std::optional<int> exit_status_;
  std::string output_path_;
};

}  // namespace test
}  // namespace flexmbd
