#pragma once
/// @file
/// Reads a whole text file.

#include <string>

namespace flexmbd {

/// Contents of the file at `path` (a regular file or a pipe). Throws ConfigError "cannot open <what>
/// '<path>': <reason>" if it cannot be opened, and "cannot read <what> '<path>': it is a directory; expected
/// a text file" for a directory, a device or another special file.
std::string ReadTextFile(const std::string& path, const std::string& what);

}  // namespace flexmbd
