// The Unix socket's private directory: named for its process, removed with the run, and when a
// run was killed before it could remove it (SIGKILL in a uds run's first milliseconds), removed by
// the next run, which says so in its run.log.
#include "coupling/socket_directory.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

// A pid whose process is gone: a child that exited and was reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

// What a killed uds run leaves: its directory, with the socket's name in it.
std::filesystem::path leave_directory(const std::filesystem::path& temporary, pid_t pid) {
  const auto dir = temporary / ("swarmnet-uds-" + std::to_string(pid) + "-Xy12ab");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "network.sock") << "";
  return dir;
}

TEST(SocketDirectory, IsNamedForItsProcessAndRemovedWithIt) {
  std::filesystem::path path;
  {
    const SocketDirectory directory;
    path = directory.path();
    EXPECT_TRUE(
        path.filename().string().starts_with("swarmnet-uds-" + std::to_string(::getpid()) + "-"))
        << path;
    EXPECT_EQ(std::filesystem::status(path).permissions(), std::filesystem::perms::owner_all);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(SocketDirectory, OnlyThoseOfProcessesThatAreGoneAreRemoved) {
  TempDir temporary;
  const auto stale = leave_directory(temporary.path(), dead_pid());
  const auto live = leave_directory(temporary.path(), ::getpid());
  const auto other = temporary.path() / "swarmnet-uds-notapid";
  std::filesystem::create_directories(other);
  const auto removed = remove_stale_socket_directories(temporary.path());
  ASSERT_EQ(removed.size(), 1U);
  EXPECT_EQ(removed[0], stale);
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(live));
  EXPECT_TRUE(std::filesystem::exists(other));
}

// In a temporary directory of its own (TMPDIR): another test's uds run, in parallel, would
// remove the stale directory first, and this run's log would have nothing to say.
TEST(SocketDirectory, TheNextRunRemovesAKilledRunsDirectoryAndSaysSo) {
  TempDir temporary;
  const auto stale = leave_directory(temporary.path(), dead_pid());
  TempDir dir;
  const CommandResult result =
      run_swarmnet("run " SWARMNET_SOURCE_DIR
                   "/configs/quickstart.yaml --quiet --transport uds --set duration_s=0.5 --out " +
                       (dir.path() / "run").string(),
                   "TMPDIR=" + temporary.path().string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_FALSE(std::filesystem::exists(stale));
  const std::string log = read_file(dir.path() / "run" / "run.log");
  EXPECT_NE(log.find("removed " + stale.string() + ", left behind by a run that crashed"),
            std::string::npos)
      << log;
  std::error_code ignored;
  std::filesystem::remove_all(stale, ignored);
}

}  // namespace
}  // namespace swarmnet::testing
