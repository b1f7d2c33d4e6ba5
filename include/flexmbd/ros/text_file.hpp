#pragma once
/// @file
/// Reads a whole text file.

#include <string>

namespace flexmbd {
namespace ros {

/// Contents of the file at `path`. Throws ConfigError "cannot open <what> '<path>': <reason>" (the loader's
/// wording) if it cannot be read.
std::string ReadTextFile(const std::string& path, const std::string& what);

}  // namespace ros
}  // namespace flexmbd
