#include "isolated_run.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <stdexcept>
#include <string>

namespace flexmbd {
namespace fuzz {
namespace {

void WriteAll(int fd, const std::string& data) {
  size_t written = 0;
  while (written < data.size()) {
    const ssize_t n = write(fd, data.data() + written, data.size() - written);
    if (n <= 0) return;  // the parent reads a short result and reports the child as ended early
    written += static_cast<size_t>(n);
  }
}

std::string ReadAll(int fd) {
  std::string data;
  char buffer[4096];
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    data.append(buffer, static_cast<size_t>(n));
  }
  return data;
}

[[noreturn]] void RunChild(const std::function<TargetResult()>& work, const IsolationLimits& limits, int out) {
  if (limits.quiet) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
  if (limits.memory_mib > 0) {
    const rlim_t bytes = static_cast<rlim_t>(limits.memory_mib) << 20;
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
  }
  const itimerval cpu_limit{{0, 0}, {static_cast<time_t>(limits.seconds), 0}};
  setitimer(ITIMER_PROF, &cpu_limit, nullptr);
  alarm(kWallClockFactor * limits.seconds);
  const TargetResult result = work();
  // one byte of outcome, then the message; _exit skips the parent's atexit handlers and static destructors
  WriteAll(out, std::string(1, static_cast<char>(result.outcome)) + result.message);
  _exit(0);
}

}  // namespace

IsolatedResult RunIsolated(const std::function<TargetResult()>& work, const IsolationLimits& limits) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error("fuzz: cannot create a pipe");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fuzz: cannot fork");
  if (child == 0) {
    close(pipe_fds[0]);
    RunChild(work, limits, pipe_fds[1]);
  }
  close(pipe_fds[1]);
  const std::string data = ReadAll(pipe_fds[0]);
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  IsolatedResult isolated;
  if (WIFSIGNALED(status)) {
    isolated.signal = WTERMSIG(status);
    const bool timed_out = isolated.signal == SIGPROF || isolated.signal == SIGALRM;
    isolated.termination = timed_out ? Termination::kTimedOut : Termination::kCrashed;
  } else if (WEXITSTATUS(status) != 0 || data.empty()) {
    isolated.termination = Termination::kExited;
    isolated.exit_code = WEXITSTATUS(status);
  } else {
    isolated.result.outcome = static_cast<Outcome>(data[0]);
    isolated.result.message = data.substr(1);
  }
  return isolated;
}

void ExtendTimeLimit(unsigned factor) {
  itimerval cpu_limit{};
  getitimer(ITIMER_PROF, &cpu_limit);
  if (cpu_limit.it_value.tv_sec == 0 && cpu_limit.it_value.tv_usec == 0) return;  // no limit: not in a child
  const long long micro = (cpu_limit.it_value.tv_sec * 1000000LL + cpu_limit.it_value.tv_usec) * factor;
  cpu_limit.it_value = {static_cast<time_t>(micro / 1000000), static_cast<suseconds_t>(micro % 1000000)};
  setitimer(ITIMER_PROF, &cpu_limit, nullptr);
  const unsigned wall_left = alarm(0);
  if (wall_left > 0) alarm(wall_left * factor);
}

double CpuSecondsLeft() {
  itimerval cpu_limit{};
  getitimer(ITIMER_PROF, &cpu_limit);
  return cpu_limit.it_value.tv_sec + 1e-6 * cpu_limit.it_value.tv_usec;
}

}  // namespace fuzz
}  // namespace flexmbd
