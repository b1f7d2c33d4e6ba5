#include "flexmbd/io/text_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "flexmbd/common/error.hpp"

namespace flexmbd {

namespace {
// What kind of file `mode` is, if it is not text one can read to its end: a directory opens but reads as
// empty (an empty YAML would run the defaults), and a device such as /dev/zero never ends. Pipes are
// accepted so that `--config <(...)` works.
const char* NotTextFileKind(mode_t mode) {
  if (S_ISREG(mode) || S_ISFIFO(mode)) return nullptr;
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  return "a special file";
}
}  // namespace

std::string ReadTextFile(const std::string& path, const std::string& what) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    throw ConfigError("cannot open " + what + " '" + path + "': " + std::strerror(errno));
  }
  if (const char* kind = NotTextFileKind(status.st_mode)) {
    throw ConfigError("cannot read " + what + " '" + path + "': it is " + kind + "; expected a text file");
  }
  std::ifstream file(path);
  if (!file) throw ConfigError("cannot open " + what + " '" + path + "': " + std::strerror(errno));
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw ConfigError("cannot read " + what + " '" + path + "': " + std::strerror(errno));
  return text.str();
}

}  // namespace flexmbd
