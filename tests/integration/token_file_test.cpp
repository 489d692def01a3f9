// The token file's rules (docs/security.md): a FIFO is refused at once instead of blocking open()
// forever, and a symbolic link, a FIFO or a device is refused saying how to fix it.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <future>
#include <string>

#include "command_runner.hpp"
#include "coupling/peer_secret.hpp"
#include "outputs/run_error.hpp"

namespace swarmnet::testing {
namespace {

// The message PeerSecret::from_file refuses `path` with, or "" if it accepted it. A call still
// blocked after 5 s fails the test; a writer then opens the FIFO to let it return.
std::string refusal(const std::filesystem::path& path) {
  auto reading = std::async(std::launch::async, [path]() -> std::string {
    try {
      PeerSecret::from_file(path);
      return "";
    } catch (const RunError& error) {
      return error.what();
    }
  });
  if (reading.wait_for(std::chrono::seconds(5)) != std::future_status::ready) {
    ADD_FAILURE() << "reading the token file " << path << " blocks";
    const int writer = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if (writer >= 0) ::close(writer);
  }
  return reading.get();
}

void write_token(const std::filesystem::path& path) {
  std::ofstream(path) << "correct horse battery staple 42\n";
  ::chmod(path.c_str(), 0600);
}

TEST(TokenFile, AFifoIsRefusedAtOnceSayingWhatToDo) {
  TempDir dir;
  const auto fifo = dir.path() / "token";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string why = refusal(fifo);
  EXPECT_EQ(why, "token file " + fifo.string() +
                     ": is a FIFO, not a regular file; write the token into a regular file only "
                     "you can read (head -c 32 /dev/urandom | base64 > FILE; chmod 600 FILE) and "
                     "name that");
}

TEST(TokenFile, ASymbolicLinkIsRefusedNamingTheFileToUseInstead) {
  TempDir dir;
  const auto real = dir.path() / "real-token";
  write_token(real);
  const auto link = dir.path() / "token";
  std::filesystem::create_symlink(real, link);
  EXPECT_EQ(refusal(real), "");  // the file itself is a good token
  EXPECT_EQ(refusal(link), "token file " + link.string() +
                               ": is a symbolic link; a token file is not read through one (the "
                               "link could be pointed elsewhere); name the file itself: " +
                               std::filesystem::canonical(real).string());
}

TEST(TokenFile, ADeviceIsRefusedAsNotARegularFile) {
  const std::string why = refusal("/dev/null");
  EXPECT_NE(why.find("token file /dev/null: is a character device, not a regular file; "),
            std::string::npos)
      << why;
}

// As a user meets it: `swarmnet run --net` with a FIFO for a token returns with the reason.
TEST(TokenFile, ARunGivenAFifoForItsTokenStopsWithTheReason) {
  TempDir dir;
  const auto fifo = dir.path() / "token";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const CommandResult result =
      run_swarmnet("run " SWARMNET_SOURCE_DIR
                   "/configs/quickstart.yaml --quiet --net "
                   "tcp://127.0.0.1:9 --token-file " +
                   fifo.string() + " --out " + (dir.path() / "run").string());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(fifo.string() + ": is a FIFO, not a regular file"),
            std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace swarmnet::testing
