// WholeLineFileBuffer (include/flexmbd/io/whole_line_file_buffer.hpp): a write that fails part-way leaves the
// file with whole lines only, and lines_written() counts them. The failures are real ones: a file size cap
// (RLIMIT_FSIZE, EFBIG) and /dev/full (ENOSPC).

#include "flexmbd/io/whole_line_file_buffer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

#include "../integration/helpers/file_size_limit.hpp"

namespace flexmbd {
namespace whole_line_file_buffer_test {

// Each line is "row NNNNN\n": 10 bytes.
constexpr int kLineBytes = 10;

void WriteLine(std::ostream& out, int k) { out << "row " << std::setfill('0') << std::setw(5) << k << '\n'; }

std::string FileText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string ExpectedLines(int count) {
  std::ostringstream text;
  for (int k = 0; k < count; ++k) WriteLine(text, k);
  return text.str();
}

TEST(WholeLineFileBuffer, CapHitAtCloseLeavesTheWholeLinesBeforeIt) {
  // 20 lines (200 bytes, all buffered until Close) against a 95-byte cap: the kernel takes 95 bytes, 9 whole
  // lines and half of the 10th, which is cut off.
  const std::string path = testing::TempDir() + "whole_lines_close.txt";
  bool closed = true;
  long lines = -1;
  std::string error;
  {
    const test::FileSizeLimit cap(95);
    WholeLineFileBuffer file(path);
    ASSERT_TRUE(file.is_open()) << file.error();
    std::ostream out(&file);
    for (int k = 0; k < 20; ++k) WriteLine(out, k);
    EXPECT_TRUE(out.good());  // nothing written yet
    closed = file.Close();
    lines = file.lines_written();
    error = file.error();
  }
  EXPECT_FALSE(closed);
  EXPECT_EQ(lines, 9);
  EXPECT_EQ(FileText(path), ExpectedLines(9));
  EXPECT_EQ(error, "File too large");
}

TEST(WholeLineFileBuffer, CapHitMidStreamFailsTheStreamAndKeepsWholeLines) {
  // 20000 lines (200000 bytes) against a cap of 70005 bytes: the first buffer (65536 bytes) goes out whole,
  // the second only up to the cap; the 7000 whole lines stay, the 5 bytes of the 7001st are cut off, and the
  // stream fails before Close.
  const std::string path = testing::TempDir() + "whole_lines_stream.txt";
  bool stream_failed = false;
  long lines = -1;
  {
    const test::FileSizeLimit cap(7000 * kLineBytes + 5);
    WholeLineFileBuffer file(path);
    std::ostream out(&file);
    for (int k = 0; k < 20000; ++k) WriteLine(out, k);
    stream_failed = !out;
    EXPECT_FALSE(file.Close());
    lines = file.lines_written();
  }
  EXPECT_TRUE(stream_failed);
  EXPECT_EQ(lines, 7000);
  EXPECT_EQ(FileText(path), ExpectedLines(7000));
}

TEST(WholeLineFileBuffer, FullDeviceTakesNoLine) {
  WholeLineFileBuffer file("/dev/full");
  ASSERT_TRUE(file.is_open()) << file.error();
  std::ostream out(&file);
  WriteLine(out, 0);
  EXPECT_FALSE(file.Close());
  EXPECT_EQ(file.lines_written(), 0);
  EXPECT_EQ(file.error(), "No space left on device");
}

TEST(WholeLineFileBuffer, UnwritablePathIsNotOpenAndSaysWhy) {
  const WholeLineFileBuffer file("/nonexistent_dir/out.csv");
  EXPECT_FALSE(file.is_open());
  EXPECT_EQ(file.error(), "No such file or directory");
}

}  // namespace whole_line_file_buffer_test
}  // namespace flexmbd
