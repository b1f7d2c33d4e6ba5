// Every test process (a shard of a gtest layer, a rostest's test node) writes its files in a directory of its own
// under TEST_TMPDIR. Shards and rostests run side by side, and a case that tests in two shards share (a run made
// once per process) was written to the same file by both: one shard then read the other's file half rewritten
// (WingAileronLco under the sanitizers). Without TEST_TMPDIR (a developer running one binary) files go to /tmp,
// gtest's own default.

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace flexmbd {
namespace own_temp_dir {
namespace {

// Before main: testing::TempDir() reads TEST_TMPDIR at every call.
const bool kMoved = [] {
  const char* base = std::getenv("TEST_TMPDIR");
  if (base == nullptr || *base == '\0') return false;
  const std::string own = std::string(base) + "/process_" + std::to_string(getpid());
  if (mkdir(own.c_str(), 0700) != 0) return false;
  setenv("TEST_TMPDIR", own.c_str(), 1);
  return true;
}();

}  // namespace
}  // namespace own_temp_dir
}  // namespace flexmbd
