#pragma once
// A full disk for a test, without privileges: RLIMIT_FSIZE caps the size of every file the process (and the
// commands it starts) writes, and with SIGXFSZ ignored a write past the cap fails with EFBIG, as one on a
// full disk fails with ENOSPC.

#include <sys/resource.h>

#include <csignal>
#include <stdexcept>

namespace flexmbd {
namespace test {

/// Caps the files written by this process and its children at `bytes` while it lives; restores the cap and
/// SIGXFSZ's handler on destruction. Throws if the cap cannot be set (it would test nothing).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    if (getrlimit(RLIMIT_FSIZE, &saved_) != 0) throw std::runtime_error("getrlimit(RLIMIT_FSIZE) failed");
    rlimit capped = saved_;
    capped.rlim_cur = bytes;
    if (setrlimit(RLIMIT_FSIZE, &capped) != 0) throw std::runtime_error("setrlimit(RLIMIT_FSIZE) failed");
    saved_handler_ = std::signal(SIGXFSZ, SIG_IGN);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, saved_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*saved_handler_)(int) = SIG_DFL;
};

}  // namespace test
}  // namespace flexmbd
