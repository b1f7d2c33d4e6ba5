#include "flexmbd/io/output_path.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace flexmbd {

const char kOutputPathExpected[] = "a writable file path (\"\" for none)";

namespace {
// What keeps a file from being written at `path`, as the end of a sentence starting with the quoted path; empty if
// nothing does.
std::string OutputPathProblem(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) == 0) {
    if (S_ISDIR(info.st_mode)) return "is a directory";
    if (access(path.c_str(), W_OK) != 0) return std::string("is not writable (") + std::strerror(errno) + ")";
    return "";
  }
  // A new file: its directory must exist and take it (a path ending in '/' names a directory, never a file).
  if (!path.empty() && path.back() == '/') return "names a directory";
  const size_t slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (stat(directory.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
    return "is in '" + directory + "', which is not an existing directory";
  }
  if (access(directory.c_str(), W_OK | X_OK) != 0) {
    return "is in '" + directory + "', which is not writable (" + std::strerror(errno) + ")";
  }
  return "";
}
}  // namespace

std::string OutputPathError(const std::string& path) {
  const std::string problem = OutputPathProblem(path);
  return problem.empty() ? "" : "'" + path + "' " + problem + "; expected " + kOutputPathExpected;
}

}  // namespace flexmbd
