#pragma once
// Checks a CSV that a failed write cut short (CsvSink, OutputError): whole rows only, as many as the error
// message claims.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

namespace flexmbd {
namespace test {

/// The lines of the file at `path`, without their '\n'.
inline std::vector<std::string> FileLines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// N in "... the file holds its header row and the first N samples"; -1 if the message has no such count.
inline long SamplesClaimed(const std::string& message) {
  const std::string lead = "the first ";
  const size_t at = message.find(lead);
  return at == std::string::npos ? -1 : std::stol(message.substr(at + lead.size()));
}

/// Expects the CSV at `path` to end with a whole line, to have a header and at least one sample, every row as
/// many fields as the header, and as many samples as `message` claims.
inline void ExpectWholeRowsAsClaimed(const std::string& path, const std::string& message) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "the last row is cut";
  const std::vector<std::string> lines = FileLines(path);
  ASSERT_GE(lines.size(), 2u) << "no sample in " << path;
  EXPECT_EQ(SamplesClaimed(message), static_cast<long>(lines.size()) - 1) << message;
  const auto commas = [](const std::string& line) { return std::count(line.begin(), line.end(), ','); };
  for (size_t k = 1; k < lines.size(); ++k) EXPECT_EQ(commas(lines[k]), commas(lines[0])) << "row " << k;
}

}  // namespace test
}  // namespace flexmbd
