#include "outputs/run_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "outputs/run_error.hpp"

namespace swarmnet {

namespace {

// Room kept ahead of the text: a run's log is a few kilobytes; the failure line must always fit.
constexpr off_t kReserveBytes = 64 * 1024;
constexpr off_t kFailureRoomBytes = 4 * 1024;
constexpr std::chrono::seconds kLongestProgressInterval{60};

}  // namespace

RunLog::RunLog(std::filesystem::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".partial-" + std::to_string(::getpid());
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    throw RunError("cannot create " + temporary_.string() + ": " + std::strerror(errno));
  }
  if (!reserve(kReserveBytes)) {
    const int error = errno;
    ::close(fd_);
    ::unlink(temporary_.c_str());
    throw RunError("cannot reserve room for " + path_.string() + ": " + std::strerror(error));
  }
  next_progress_ = std::chrono::steady_clock::now() + progress_interval_;
}

RunLog::~RunLog() {
  if (fd_ >= 0) ::close(fd_);
}

bool RunLog::reserve(off_t end) {
  if (end <= reserved_) return true;
  // KEEP_SIZE: the room is held beyond the end of the file, so the file holds only text (a
  // killed run's log has no trailing zeros).
  const int status = ::fallocate(fd_, FALLOC_FL_KEEP_SIZE, 0, end);
  if (status == 0) {
    reserved_ = end;
    return true;
  }
  // A file system that cannot reserve room: written as it goes, as any file.
  if (errno == EOPNOTSUPP) {
    reserved_ = end;
    return true;
  }
  return false;
}

bool RunLog::write_at_end(const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t wrote =
        ::pwrite(fd_, text.data() + done, text.size() - done, length_ + static_cast<off_t>(done));
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) {
      if (wrote == 0) errno = ENOSPC;
      return false;
    }
    done += static_cast<std::size_t>(wrote);
  }
  length_ += static_cast<off_t>(text.size());
  return true;
}

void RunLog::line(const std::string& text) {
  const std::string written = text + '\n';
  const off_t end = length_ + static_cast<off_t>(written.size());
  // The failure line's room stays free for it.
  if (!reserve(end + kFailureRoomBytes + kReserveBytes / 2) &&
      end + kFailureRoomBytes > reserved_) {
    throw RunError("cannot write " + path_.string() + ": " + std::strerror(errno));
  }
  if (!write_at_end(written)) {
    throw RunError("cannot write " + path_.string() + ": " + std::strerror(errno));
  }
}

void RunLog::fail(const std::string& text) noexcept {
  try {
    std::string written = text;
    const off_t room = std::max<off_t>(reserved_ - length_, kFailureRoomBytes) - 1;
    if (!reserve(length_ + static_cast<off_t>(written.size()) + 1) &&
        static_cast<off_t>(written.size()) > room) {
      const std::string more = "... (" + std::to_string(written.size()) + " bytes)";
      written.resize(static_cast<std::size_t>(room) - more.size());
      written += more;
    }
    write_at_end(written + '\n');
    commit();
  } catch (...) {
    // Nothing more can be said: the run's own error is reported on the terminal.
  }
}

void RunLog::progress(std::uint64_t step, std::uint64_t steps, double step_s) {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_progress_) return;
  progress_interval_ = std::min(progress_interval_ * 2, kLongestProgressInterval);
  next_progress_ = now + progress_interval_;
  char text[160];
  std::snprintf(text, sizeof text, "at step %llu of %llu, %.3f s simulated",
                static_cast<unsigned long long>(step), static_cast<unsigned long long>(steps),
                static_cast<double>(step) * step_s);
  line(text);
}

void RunLog::commit() {
  // The room not used is given back; the text stays.
  if (::ftruncate(fd_, length_) != 0 || ::fsync(fd_) != 0) {
    throw RunError("cannot sync " + path_.string() + ": " + std::strerror(errno));
  }
  if (committed_) return;
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw RunError("cannot rename " + temporary_.string() + " into place: " + std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace swarmnet
