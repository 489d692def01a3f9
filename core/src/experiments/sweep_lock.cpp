#include "experiments/sweep_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "outputs/run_error.hpp"

namespace swarmnet {

SweepLock::SweepLock(const std::filesystem::path& out) {
  const std::filesystem::path path = out / ".sweep.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
  if (fd_ < 0) throw RunError("cannot open " + path.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    char holder[32] = {};
    const ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
    ::close(fd_);
    throw RunError("another sweep" +
                   (n > 0 ? " (pid " + std::string(holder, static_cast<std::size_t>(n)) + ")"
                          : std::string()) +
                   " is running into " + out.string() + "; wait for it or stop it first");
  }
  const std::string pid = std::to_string(::getpid());
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The lock holds without the pid; the pid only makes the refusal message clearer.
  }
}

SweepLock::~SweepLock() { ::close(fd_); }

}  // namespace swarmnet
