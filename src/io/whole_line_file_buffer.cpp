#include "flexmbd/io/whole_line_file_buffer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace flexmbd {
namespace {
// Bytes buffered between writes: one system call per many rows, as std::filebuf's own buffer would give.
constexpr size_t kBufferBytes = 64 * 1024;
}  // namespace

WholeLineFileBuffer::WholeLineFileBuffer(const std::string& path)
    : fd_(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666)) {
  if (fd_ < 0) {
    error_ = std::strerror(errno);
    return;
  }
  buffer_.resize(kBufferBytes);
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

WholeLineFileBuffer::~WholeLineFileBuffer() { Close(); }

bool WholeLineFileBuffer::Close() {
  if (fd_ < 0) return error_.empty();
  if (error_.empty()) WriteBuffer();
  if (::close(fd_) != 0 && error_.empty()) error_ = std::strerror(errno);
  fd_ = -1;
  setp(nullptr, nullptr);
  return error_.empty();
}

WholeLineFileBuffer::int_type WholeLineFileBuffer::overflow(int_type c) {
  if (fd_ < 0 || !error_.empty() || !WriteBuffer()) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int WholeLineFileBuffer::sync() { return fd_ >= 0 && error_.empty() && WriteBuffer() ? 0 : -1; }

bool WholeLineFileBuffer::WriteBuffer() {
  const char* data = pbase();
  const size_t size = pptr() - pbase();
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd_, data + done, size - done);
    if (n > 0) {
      done += n;
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      const std::string why = n < 0 ? std::strerror(errno) : "the file takes no more bytes";
      CountLines(data, done);  // a short write before the failure: those bytes are in the file
      Fail(why);
      return false;
    }
  }
  CountLines(data, size);
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return true;
}

void WholeLineFileBuffer::CountLines(const char* data, size_t size) {
  for (size_t k = 0; k < size; ++k) {
    if (data[k] != '\n') continue;
    ++lines_written_;
    whole_lines_bytes_ = bytes_written_ + static_cast<long long>(k) + 1;
  }
  bytes_written_ += static_cast<long long>(size);
}

void WholeLineFileBuffer::Fail(const std::string& why) {
  error_ = why;
  setp(nullptr, nullptr);  // every later write overflows, and fails
  // a device (/dev/full, a pipe) cannot be cut (EINVAL); a regular file always can, in practice
  if (bytes_written_ > whole_lines_bytes_ && ::ftruncate(fd_, whole_lines_bytes_) != 0 && errno != EINVAL) {
    error_ += "; its cut last line could not be removed: " + std::string(std::strerror(errno));
  }
}

}  // namespace flexmbd
