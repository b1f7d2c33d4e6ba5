#pragma once
/// @file
/// Numbers in messages: the core's (model building) and the loader's say a value the same way.

#include <string>

namespace flexmbd {

/// Shortest decimal text that reads back as exactly `value` ("-3", "0.1", "1e-07").
std::string FormatNumber(double value);

}  // namespace flexmbd
