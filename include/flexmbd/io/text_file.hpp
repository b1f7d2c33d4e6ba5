#pragma once
/// @file
/// Reads a whole text file.

#include <string>

namespace flexmbd {

/// Contents of the file at `path`. Throws ConfigError "cannot open <what> '<path>': <reason>"
/// if it cannot be read.
std::string ReadTextFile(const std::string& path, const std::string& what);

}  // namespace flexmbd
