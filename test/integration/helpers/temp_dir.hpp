#pragma once
// A fresh directory for a test's files (bags, CSVs), removed with its contents when the test is done.

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace flexmbd {
namespace test {

class TempDir {
 public:
  /// Creates /tmp/<prefix>_XXXXXX.
  explicit TempDir(const std::string& prefix) {
    std::string pattern = "/tmp/" + prefix + "_XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a directory like " + pattern);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// The path of `name` in the directory.
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

}  // namespace test
}  // namespace flexmbd
