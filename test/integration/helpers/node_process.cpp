#include "node_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace flexmbd {
namespace test {
namespace {
// How often WaitForExit looks at the child: short against the node's start-up and shutdown (~100 ms).
constexpr std::chrono::milliseconds kExitPollPeriod(10);
}  // namespace

NodeProcess::NodeProcess(const std::string& name, const std::vector<std::string>& arguments) {
  char path[] = "/tmp/flexmbd_node_output_XXXXXX";
  const int output = mkstemp(path);
  if (output < 0) throw std::runtime_error("cannot create the node's output file");
  output_path_ = path;
  std::vector<std::string> argv_text{FLEXMBD_NODE, "__name:=" + name};
  argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& text : argv_text) argv.push_back(text.data());
  argv.push_back(nullptr);
  pid_ = fork();
  if (pid_ == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // a test that crashes takes its node down (the node stops cleanly)
    dup2(output, STDOUT_FILENO);
    dup2(output, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(output);
  if (pid_ < 0) throw std::runtime_error("cannot start " + argv_text[0]);
}

NodeProcess::~NodeProcess() {
  if (pid_ > 0 && !exited_) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  unlink(output_path_.c_str());
}

void NodeProcess::Interrupt() {
  if (!exited_) kill(pid_, SIGINT);
}

std::optional<int> NodeProcess::WaitForExit(std::chrono::milliseconds timeout) {
  if (exited_) return exit_status_;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (waitpid(pid_, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) return std::nullopt;
    std::this_thread::sleep_for(kExitPollPeriod);
  }
  exited_ = true;
  if (WIFEXITED(status)) exit_status_ = WEXITSTATUS(status);
  return exit_status_;
}

std::string NodeProcess::Output() const {
  std::ifstream file(output_path_);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace test
}  // namespace flexmbd
