// A run on a disk that fills at every point of the run: at the start (no room for run.log),
// while the traces are written, at their commit, at summary.json. Whatever point the disk fills
// at, the run either finished with every output, or it failed, says "No space left on device",
// leaves no output under its final name (only run.log and scenario.resolved.yaml, which say what
// ran and why it failed) and no temporary file, and its run.log ends with the reason; only when
// even run.log's room could not be reserved is the reason on the terminal alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "../outputs/small_tmpfs.hpp"
#include "command_runner.hpp"

namespace swarmnet::testing {
namespace {

constexpr std::array kRunOutputs = {"summary.json",  "packets.csv",  "mobility.ns2",
                                    "positions.bin", "headings.bin", "traffic.csv"};

struct Tally {
  int finished = 0;
  int failed_with_log = 0;
  int refused_before_the_log = 0;
};

CommandResult run_into(const std::filesystem::path& dir, const std::string& transport) {
  return run_swarmnet("run " SWARMNET_SOURCE_DIR "/configs/quickstart.yaml --quiet --transport " +
                      transport + " --set duration_s=2 --set output.packet_trace=true --out " +
                      dir.string());
}

void check_run(const std::filesystem::path& dir, const CommandResult& result,
               const std::string& where, Tally& tally) {
  SCOPED_TRACE(where);
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.insert(entry.path().filename().string());
  }
  for (const std::string& name : names) {
    EXPECT_EQ(name.find(".partial-"), std::string::npos) << name << "\n" << result.output;
  }
  if (result.exit_code == 0) {
    for (const char* name : kRunOutputs) EXPECT_TRUE(names.contains(name)) << name;
    EXPECT_NE(read_file(dir / "run.log").find("finished: "), std::string::npos);
    ++tally.finished;
    return;
  }
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("No space left on device"), std::string::npos) << result.output;
  for (const char* name : kRunOutputs) {
    EXPECT_FALSE(names.contains(name)) << name << " of a failed run\n" << result.output;
  }
  for (const std::string& name : names) {
    EXPECT_TRUE(name == "run.log" || name == "scenario.resolved.yaml") << name;
  }
  if (names.contains("run.log")) {
    const std::string log = read_file(dir / "run.log");
    EXPECT_NE(log.find("\nrun failed: "), std::string::npos) << log;
    EXPECT_TRUE(log.ends_with("No space left on device\n")) << log;
    EXPECT_EQ(log.find("finished: "), std::string::npos) << log;
    ++tally.failed_with_log;
  } else {
    EXPECT_NE(result.output.find("cannot reserve room for " + (dir / "run.log").string() +
                                 ": No space left on device"),
              std::string::npos)
        << result.output;
    ++tally.refused_before_the_log;
  }
}

// The free space of every run: coarse steps from nothing to more than the run needs, and page
// steps around what it needs (where the commit and summary.json are).
std::vector<std::uint64_t> free_space_points(std::uint64_t needed) {
  std::vector<std::uint64_t> points;
  const std::uint64_t top = needed + 128 * 1024;
  for (std::uint64_t free = 0; free <= top; free += std::max<std::uint64_t>(top / 24, 4096)) {
    points.push_back(free);
  }
  const std::uint64_t page = 4096;
  for (std::uint64_t free = needed > 64 * 1024 ? needed - 64 * 1024 : 0; free <= needed + 16 * 1024;
       free += page) {
    points.push_back(free);
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

void fill_at_every_point(const std::string& transport) {
  SmallTmpfs disk(8 * 1024 * 1024);
  if (!disk.why_not().empty()) GTEST_SKIP() << disk.why_not();
  const std::filesystem::path dir = disk.path() / "run";
  // What a whole run takes on this file system (its files, and run.log's reserved room).
  const std::uint64_t empty = disk.free_bytes();
  const CommandResult whole = run_into(dir, transport);
  ASSERT_EQ(whole.exit_code, 0) << whole.output;
  const std::uint64_t needed = empty - disk.free_bytes() + 64 * 1024;
  std::filesystem::remove_all(dir);

  Tally tally;
  for (const std::uint64_t free : free_space_points(needed)) {
    std::filesystem::remove_all(dir);
    ASSERT_TRUE(disk.leave_free(free)) << free;
    const CommandResult result = run_into(dir, transport);
    check_run(dir, result, transport + ", " + std::to_string(free) + " bytes free", tally);
  }
  std::printf("%s: %zu points, %d finished, %d failed with run.log, %d refused before it\n",
              transport.c_str(), free_space_points(needed).size(), tally.finished,
              tally.failed_with_log, tally.refused_before_the_log);
  // The sweep reached each outcome: else it tested less than it says.
  EXPECT_GT(tally.finished, 0);
  EXPECT_GT(tally.failed_with_log, 10);
  EXPECT_GT(tally.refused_before_the_log, 0);
}

TEST(DiskFull, ARunFillingTheDiskAnywhereSaysWhyAndLeavesNoOutput) { fill_at_every_point("shm"); }

// In process the network half's traces carry this process's pid: the same commit applies.
TEST(DiskFull, AnInProcessRunFillingTheDiskSaysWhyAndLeavesNoOutput) {
  fill_at_every_point("inproc");
}

}  // namespace
}  // namespace swarmnet::testing
