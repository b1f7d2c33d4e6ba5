#pragma once
// Case files as text, and single edits of that text, for tests that run the runner on a variant of a YAML file.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

namespace flexmbd {
namespace test {

/// The whole text of the file at `path` ("" if it cannot be read).
inline std::string ReadFile(const std::string& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

/// `text` with its one occurrence of `from` replaced by `to`; a missing `from` fails the test.
inline std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace test
}  // namespace flexmbd
