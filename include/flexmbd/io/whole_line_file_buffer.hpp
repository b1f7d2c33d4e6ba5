#pragma once
/// @file
/// A stream buffer over a file that never leaves a cut line in it: when a write fails (disk full, file size
/// limit, I/O error), the file is cut back to the end of its last whole line, every later write fails, and
/// lines_written() says how many whole lines the file holds. std::filebuf cannot: after a failed write it
/// does not say how much of its buffer reached the file.
///
/// @code
///   WholeLineFileBuffer file("out.csv");
///   std::ostream out(&file);
///   out << "t,x\n" << 0.0 << ',' << 1.0 << '\n';
///   if (!out || !file.Close()) Report(file.error(), file.lines_written());
/// @endcode

#include <streambuf>
#include <string>
#include <vector>

namespace flexmbd {

class WholeLineFileBuffer : public std::streambuf {
 public:
  /// Creates or truncates the file at `path`; is_open() says whether that worked, error() why not.
  explicit WholeLineFileBuffer(const std::string& path);
  /// Closes the file as Close() does; a failure then goes unreported (call Close() to learn of it).
  ~WholeLineFileBuffer() override;
  WholeLineFileBuffer(const WholeLineFileBuffer&) = delete;
  WholeLineFileBuffer& operator=(const WholeLineFileBuffer&) = delete;

  bool is_open() const { return fd_ >= 0; }

  /// Writes what is buffered and closes the file. False if that or any earlier write failed (error()).
  bool Close();

  /// Whole lines in the file (not those still buffered).
  long lines_written() const { return lines_written_; }

  /// Why opening or writing failed (the system's text, e.g. "No space left on device"); empty if nothing
  /// failed.
  const std::string& error() const { return error_; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;

 private:
  /// Writes the buffer to the file and empties it; on failure cuts the file back to its whole lines.
  bool WriteBuffer();
  /// Counts the whole lines among `size` bytes just written at the end of the file.
  void CountLines(const char* data, size_t size);
  void Fail(const std::string& why);

  int fd_ = -1;
  std::vector<char> buffer_;
  long long bytes_written_ = 0;     ///< bytes in the file [B]
  long long whole_lines_bytes_ = 0;  ///< bytes in the file up to the end of its last whole line [B]
  long lines_written_ = 0;
  std::string error_;
};

}  // namespace flexmbd
