#include "flexmbd/io/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "flexmbd/common/error.hpp"

namespace flexmbd {

std::string ReadTextFile(const std::string& path, const std::string& what) {
  std::ifstream file(path);
  if (!file) throw ConfigError("cannot open " + what + " '" + path + "': " + std::strerror(errno));
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace flexmbd
