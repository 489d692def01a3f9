#include "coupling/socket_directory.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>

#include "outputs/run_error.hpp"

namespace swarmnet {

namespace {

constexpr const char* kPrefix = "swarmnet-uds-";

}  // namespace

SocketDirectory::SocketDirectory() {
  const std::filesystem::path temporary = std::filesystem::temp_directory_path();
  std::string pattern = (temporary / (kPrefix + std::to_string(::getpid()) + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw RunError("cannot create a directory for the network half's socket in " +
                   temporary.string() + ": " + std::strerror(errno));
  }
  path_ = pattern;
}

SocketDirectory::~SocketDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::vector<std::filesystem::path> remove_stale_socket_directories(
    const std::filesystem::path& temporary) {
  std::vector<std::filesystem::path> removed;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(temporary, ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(kPrefix)) continue;
    const std::string rest = name.substr(std::char_traits<char>::length(kPrefix));
    char* end = nullptr;
    const long pid = std::strtol(rest.c_str(), &end, 10);
    if (pid <= 0 || end == rest.c_str() || *end != '-') continue;
    // Only this user's directories, and only once their process is gone (ESRCH).
    struct stat info {};
    if (::lstat(entry.path().c_str(), &info) != 0 || !S_ISDIR(info.st_mode) ||
        info.st_uid != ::geteuid()) {
      continue;
    }
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code removing;
    if (std::filesystem::remove_all(entry.path(), removing) > 0 && !removing) {
      removed.push_back(entry.path());
    }
  }
  std::sort(removed.begin(), removed.end());
  return removed;
}

}  // namespace swarmnet
