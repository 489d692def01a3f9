#include "outputs/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "outputs/run_error.hpp"

namespace swarmnet {

namespace {

// A large buffer: traces are written line by line.
constexpr std::size_t kBufferBytes = std::size_t{1} << 20U;

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".partial-" + std::to_string(::getpid());
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) fail("cannot create", errno);
  buffer_.emplace(fd_, kBufferBytes);
  stream_.rdbuf(&*buffer_);
}

AtomicFile::~AtomicFile() {
  close_descriptor();
  if (!kept_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicFile::close_descriptor() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void AtomicFile::fail(const std::string& what, int error) const {
  throw RunError(what + " " + path_.string() + ": " + std::strerror(error));
}

void AtomicFile::finish() {
  if (finished_) return;
  stream_.flush();
  if (!buffer_->drain()) fail("cannot write", buffer_->error());
  // A formatting failure, not the disk's (every failed write sets the buffer's error).
  if (stream_.bad()) fail("cannot write", EIO);
  // fsync so that a crash right after the rename cannot leave an empty file under the final name.
  if (::fsync(fd_) != 0) fail("cannot sync", errno);
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) fail("cannot write", errno);
  finished_ = true;
}

void AtomicFile::commit() {
  finish();
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) fail("cannot rename into place", errno);
  kept_ = true;
}

void AtomicFile::hand_over() {
  finish();
  kept_ = true;
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace swarmnet
