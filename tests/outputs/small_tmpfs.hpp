// A small tmpfs the test mounts to fill a disk on purpose (root only: other users skip the test
// with the reason), and a filler file that leaves exactly so many bytes free on it.
#pragma once

#include <fcntl.h>
#include <sys/mount.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace swarmnet::testing {

class SmallTmpfs {
 public:
  explicit SmallTmpfs(std::uint64_t bytes) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "swarmnet-tmpfs-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      why_not_ = std::string("mkdtemp: ") + std::strerror(errno);
      return;
    }
    path_ = pattern;
    if (::geteuid() != 0) {
      why_not_ = "mounting a small tmpfs to fill needs root";
      return;
    }
    const std::string options = "size=" + std::to_string(bytes) + ",mode=0755";
    if (::mount("tmpfs", path_.c_str(), "tmpfs", 0, options.c_str()) != 0) {
      why_not_ = std::string("cannot mount a tmpfs (a container without CAP_SYS_ADMIN?): ") +
                 std::strerror(errno);
      return;
    }
    mounted_ = true;
  }
  ~SmallTmpfs() {
    if (mounted_) ::umount2(path_.c_str(), MNT_DETACH);
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  SmallTmpfs(const SmallTmpfs&) = delete;
  SmallTmpfs& operator=(const SmallTmpfs&) = delete;

  // Empty when mounted; else why not (the test skips with it).
  [[nodiscard]] const std::string& why_not() const { return why_not_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  [[nodiscard]] std::uint64_t free_bytes() const {
    struct statvfs info {};
    if (::statvfs(path_.c_str(), &info) != 0) return 0;
    return static_cast<std::uint64_t>(info.f_bavail) * info.f_frsize;
  }

  // Grows (or replaces) the filler file so that `free` bytes stay free (rounded down to pages).
  // False if that is not possible.
  bool leave_free(std::uint64_t free) {
    const std::filesystem::path filler = path_ / "filler";
    std::error_code ignored;
    std::filesystem::remove(filler, ignored);
    const std::uint64_t available = free_bytes();
    if (free > available) return false;
    if (free == available) return true;
    const int fd = ::open(filler.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) return false;
    const bool ok = ::posix_fallocate(fd, 0, static_cast<off_t>(available - free)) == 0;
    ::close(fd);
    return ok;
  }

 private:
  std::filesystem::path path_;
  std::string why_not_;
  bool mounted_ = false;
};

}  // namespace swarmnet::testing
