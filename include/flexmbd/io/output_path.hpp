#pragma once
/// @file
/// Checks, before a run, that an output file (output.csv, output.bag) can be created where it is asked for.

#include <string>

namespace flexmbd {

/// What keeps a file from being written at `path`, as the end of a sentence starting with the quoted path
/// ("is a directory", "is in 'd', which is not an existing directory", "is not writable (Permission denied)");
/// empty if nothing does. Nothing is created or truncated.
std::string OutputPathProblem(const std::string& path);

/// The expected form of an output path, for messages.
extern const char kOutputPathExpected[];

}  // namespace flexmbd
