// AtomicFile on a full disk: the failure names the file and the system's reason, nothing is left
// under the final name or the temporary one; a file handed over stays, finished, for another.
#include "outputs/atomic_file.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "outputs/positions_trace.hpp"
#include "outputs/run_error.hpp"
#include "outputs/text_file.hpp"
#include "small_tmpfs.hpp"

namespace swarmnet {
namespace {

using testing::SmallTmpfs;

TEST(AtomicFile, AFullDiskIsReportedWithTheSystemsReason) {
  SmallTmpfs disk(256 * 1024);
  if (!disk.why_not().empty()) GTEST_SKIP() << disk.why_not();
  ASSERT_TRUE(disk.leave_free(16 * 1024));
  const std::filesystem::path path = disk.path() / "packets.csv";
  std::filesystem::path temporary;
  try {
    AtomicFile file(path);
    temporary = file.temporary();
    const std::string line(1000, 'x');
    for (int i = 0; i < 100; ++i) file.stream() << line << '\n';  // 100 KB into 16 KB
    file.commit();
    FAIL() << "100 KB were written into 16 KB";
  } catch (const RunError& error) {
    EXPECT_EQ(std::string(error.what()),
              "cannot write " + path.string() + ": No space left on device");
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(temporary));
}

// A trace that seeks back to its header (a run a world ended early) on a full disk: the seek
// writes what was buffered, and its failure gives the system's reason too.
TEST(AtomicFile, ATraceRewritingItsHeaderOnAFullDiskSaysWhy) {
  SmallTmpfs disk(256 * 1024);
  if (!disk.why_not().empty()) GTEST_SKIP() << disk.why_not();
  ASSERT_TRUE(disk.leave_free(16 * 1024));
  AtomicFile file(disk.path() / "positions.bin");
  PositionsTraceWriter positions(file.stream(), 1000, 10, SimTime(100'000'000));
  const std::vector<Vec2> robots(1000, Vec2(1.0, 2.0));
  for (int step = 0; step < 2; ++step) positions.sample(robots);  // 32 KB into 16 KB, buffered
  try {
    positions.finish();
    FAIL() << "the header was rewritten on a full disk";
  } catch (const RunError& error) {
    EXPECT_EQ(std::string(error.what()),
              "cannot record the step count in the positions trace's header: No space left on "
              "device");
  }
}

TEST(AtomicFile, SeeksRewriteInPlaceAsAFileStreamDoes) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::filesystem::path path = dir / ("atomic-seek-" + std::to_string(::getpid()));
  {
    AtomicFile file(path);
    file.stream() << "header--body";
    const auto end = file.stream().tellp();
    EXPECT_EQ(static_cast<long long>(end), 12);
    file.stream().seekp(6);
    file.stream() << "++";
    file.stream().seekp(end);
    file.stream() << "!";
    file.commit();
  }
  EXPECT_EQ(read_text_file(path), "header++body!");
  std::filesystem::remove(path);
}

TEST(AtomicFile, AHandedOverFileStaysFinishedUnderItsTemporaryName) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("atomic-handed-" + std::to_string(::getpid()));
  std::filesystem::path temporary;
  {
    AtomicFile file(path);
    temporary = file.temporary();
    file.stream() << "whole\n";
    file.hand_over();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(read_text_file(temporary), "whole\n");
  std::filesystem::remove(temporary);
}

}  // namespace
}  // namespace swarmnet
