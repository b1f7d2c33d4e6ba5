#pragma once
/// @file
/// Checks, before a run, that an output file (output.csv, output.bag) can be created where it is asked for.

#include <string>

namespace flexmbd {

/// Why no file can be written at `path`, as a message's end naming the path and the expected form ("'/tmp' is a
/// directory; expected a writable file path (\"\" for none)"; also "is in 'd', which is not an existing directory",
/// "is not writable (Permission denied)"); empty if nothing keeps it from being written. Nothing is created or
/// truncated.
std::string OutputPathError(const std::string& path);

/// The expected form of an output path, for messages.
extern const char kOutputPathExpected[];

}  // namespace flexmbd
