// run.log: each line is on disk as soon as it is written (a killed run's log says how far it
// got), and a run failing on a full disk still records why, in the room reserved at its start.
#include "outputs/run_log.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "outputs/run_error.hpp"
#include "outputs/text_file.hpp"
#include "small_tmpfs.hpp"

namespace swarmnet {
namespace {

using testing::SmallTmpfs;

TEST(RunLog, LinesAreInTheFileAsSoonAsWritten) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("run-log-" + std::to_string(::getpid()));
  RunLog log(path);
  log.line("seed 1, 50 robots");
  log.line("transport: shared memory");
  // No trailing zeros from the reserved room: the file holds only the text.
  EXPECT_EQ(read_text_file(log.temporary()), "seed 1, 50 robots\ntransport: shared memory\n");
  EXPECT_FALSE(std::filesystem::exists(path));
  log.commit();
  EXPECT_EQ(read_text_file(path), "seed 1, 50 robots\ntransport: shared memory\n");
  EXPECT_FALSE(std::filesystem::exists(log.temporary()));
  log.line("run failed: after the commit");  // appended to the committed log
  EXPECT_EQ(read_text_file(path),
            "seed 1, 50 robots\ntransport: shared memory\nrun failed: after the commit\n");
  std::filesystem::remove(path);
}

TEST(RunLog, AFullDiskStillGetsTheReason) {
  SmallTmpfs disk(512 * 1024);
  if (!disk.why_not().empty()) GTEST_SKIP() << disk.why_not();
  const std::filesystem::path path = disk.path() / "run.log";
  RunLog log(path);
  log.line("SwarmNet run of scenario 'quickstart'");
  ASSERT_TRUE(disk.leave_free(0));  // every byte the log did not reserve is taken
  ASSERT_EQ(disk.free_bytes(), 0U);
  log.line("transport: shared memory");
  log.fail("run failed: cannot write " + (disk.path() / "summary.json").string() +
           ": No space left on device");
  EXPECT_EQ(read_text_file(path),
            "SwarmNet run of scenario 'quickstart'\ntransport: shared memory\n"
            "run failed: cannot write " +
                (disk.path() / "summary.json").string() + ": No space left on device\n");
}

// A log that outgrows its room on a full disk: its lines are refused with the reason before they
// take the failure line's room, which still holds the reason the run failed.
TEST(RunLog, LinesBeyondTheRoomAreRefusedButTheFailureStillFits) {
  SmallTmpfs disk(512 * 1024);
  if (!disk.why_not().empty()) GTEST_SKIP() << disk.why_not();
  const std::filesystem::path path = disk.path() / "run.log";
  RunLog log(path);
  ASSERT_TRUE(disk.leave_free(0));
  const std::string progress(99, 'p');
  std::size_t written = 0;
  try {
    for (; written < 10000; ++written) log.line(progress);
    FAIL() << "a megabyte of lines fitted in a full disk";
  } catch (const RunError& error) {
    EXPECT_EQ(std::string(error.what()),
              "cannot write " + path.string() + ": No space left on device");
  }
  EXPECT_GT(written, 500U);  // most of the 64 KiB reserved held lines
  const std::string failure =
      "run failed: cannot write " + path.string() + ": No space left on device";
  log.fail(failure);
  const std::string text = read_text_file(path);
  EXPECT_EQ(text.size(), written * 100 + failure.size() + 1);  // every line written, whole
  EXPECT_TRUE(text.ends_with("\n" + failure + "\n"));
}

TEST(RunLog, GrowsPastItsFirstRoomWhenTheDiskHasSpace) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("run-log-grows-" + std::to_string(::getpid()));
  RunLog log(path);
  const std::string progress(99, 'p');
  for (int i = 0; i < 3000; ++i) log.line(progress);  // 300 KB, past the first 64 KiB
  log.commit();
  EXPECT_EQ(std::filesystem::file_size(path), 300000U);
  std::filesystem::remove(path);
}

TEST(RunLog, AFailureTooLongForTheRoomLeftIsShortenedNotLost) {
  SmallTmpfs disk(512 * 1024);
  if (!disk.why_not().empty()) GTEST_SKIP() << disk.why_not();
  const std::filesystem::path path = disk.path() / "run.log";
  RunLog log(path);
  ASSERT_TRUE(disk.leave_free(0));
  log.fail("run failed: " + std::string(200 * 1024, 'x'));
  const std::string text = read_text_file(path);
  EXPECT_TRUE(text.starts_with("run failed: xxx")) << text.substr(0, 80);
  EXPECT_TRUE(text.ends_with("... (" + std::to_string(12 + 200 * 1024) + " bytes)\n"))
      << text.substr(text.size() - 80);
}

TEST(RunLog, NoRoomForTheLogIsRefusedWithTheReason) {
  SmallTmpfs disk(512 * 1024);
  if (!disk.why_not().empty()) GTEST_SKIP() << disk.why_not();
  ASSERT_TRUE(disk.leave_free(0));
  const std::filesystem::path path = disk.path() / "run.log";
  try {
    RunLog log(path);
    FAIL() << "a log was made on a full disk";
  } catch (const RunError& error) {
    EXPECT_EQ(std::string(error.what()),
              "cannot reserve room for " + path.string() + ": No space left on device");
  }
  // Nothing of the log is left: only the test's filler.
  for (const auto& entry : std::filesystem::directory_iterator(disk.path())) {
    EXPECT_EQ(entry.path().filename(), "filler");
  }
}

}  // namespace
}  // namespace swarmnet
