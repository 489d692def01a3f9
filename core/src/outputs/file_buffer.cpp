#include "outputs/file_buffer.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace swarmnet {

FileBuffer::FileBuffer(int fd, std::size_t capacity) : fd_(fd), buffer_(capacity) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

bool FileBuffer::drain() {
  if (error_ != 0) return false;
  const char* at = pbase();
  while (at < pptr()) {
    const ssize_t wrote = ::write(fd_, at, static_cast<std::size_t>(pptr() - at));
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) {
      // A write of 0 bytes to a regular file means no room was left for it.
      error_ = wrote < 0 ? errno : ENOSPC;
      return false;
    }
    at += wrote;
  }
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return true;
}

FileBuffer::int_type FileBuffer::overflow(int_type c) {
  if (!drain()) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int FileBuffer::sync() { return drain() ? 0 : -1; }

FileBuffer::pos_type FileBuffer::seekoff(off_type off, std::ios_base::seekdir dir,
                                         std::ios_base::openmode /*which*/) {
  if (!drain()) return {off_type(-1)};
  const int whence = dir == std::ios_base::beg   ? SEEK_SET
                     : dir == std::ios_base::cur ? SEEK_CUR
                                                 : SEEK_END;
  const off_t at = ::lseek(fd_, static_cast<off_t>(off), whence);
  if (at < 0) {
    error_ = errno;
    return {off_type(-1)};
  }
  return {static_cast<off_type>(at)};
}

FileBuffer::pos_type FileBuffer::seekpos(pos_type pos, std::ios_base::openmode which) {
  return seekoff(off_type(pos), std::ios_base::beg, which);
}

std::string write_failure(std::ostream& out) {
  const auto* file = dynamic_cast<const FileBuffer*>(out.rdbuf());
  if (file != nullptr && file->error() != 0) return std::strerror(file->error());
  return "the output stream failed";
}

}  // namespace swarmnet
