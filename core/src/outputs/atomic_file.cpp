#include "outputs/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "outputs/run_error.hpp"

namespace swarmnet {

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".partial-" + std::to_string(::getpid());
  // A large buffer: traces are written line by line. Must be set before open().
  buffer_.resize(std::size_t{1} << 20U);
  stream_.rdbuf()->pubsetbuf(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  stream_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!stream_) fail("cannot create");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    stream_.close();
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicFile::fail(const std::string& what) {
  const int error = errno;
  throw RunError(what + " " + path_.string() + ": " +
                 (error != 0 ? std::strerror(error) : "write failed"));
}

void AtomicFile::finish() {
  if (finished_) return;
  errno = 0;
  stream_.flush();
  if (!stream_) fail("cannot write");
  stream_.close();
  if (stream_.fail()) fail("cannot write");
  // fsync so that a crash right after the rename cannot leave an empty file under the final name.
  const int fd = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    if (fd >= 0) ::close(fd);
    fail("cannot sync");
  }
  ::close(fd);
  finished_ = true;
}

void AtomicFile::commit() {
  finish();
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) fail("cannot rename into place");
  committed_ = true;
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace swarmnet
