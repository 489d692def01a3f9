// The private directory (mode 0700) a run's Unix-domain socket is made in, under the system's
// temporary directory and named for the process that made it (swarmnet-uds-PID-XXXXXX), so that
// one left by a run killed before it removed it (SIGKILL in the first milliseconds of a `uds`
// run) is found and removed by the next run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace swarmnet {

class SocketDirectory {
 public:
  // Throws RunError naming the temporary directory and the system's reason.
  SocketDirectory();
  // Removes the directory and the socket in it.
  ~SocketDirectory();
  SocketDirectory(const SocketDirectory&) = delete;
  SocketDirectory& operator=(const SocketDirectory&) = delete;
  SocketDirectory(SocketDirectory&&) = delete;
  SocketDirectory& operator=(SocketDirectory&&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Removes the socket directories of this user's runs whose process is gone; returns them.
// `temporary`: where they are made (the system's temporary directory by default).
std::vector<std::filesystem::path> remove_stale_socket_directories(
    const std::filesystem::path& temporary = std::filesystem::temp_directory_path());

}  // namespace swarmnet
