// OutputCommit: outputs appear under their final names only when every rename succeeded and the
// run kept them; otherwise neither final names nor temporary files are left.
#include "outputs/output_commit.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "outputs/run_error.hpp"

namespace swarmnet {
namespace {

class OutputCommitTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("output-commit-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(OutputCommitTest, KeptOutputsAreRenamedInOrder) {
  {
    AtomicFile a(dir_ / "a.csv");
    AtomicFile b(dir_ / "b.csv");
    a.stream() << "a\n";
    b.stream() << "b\n";
    OutputCommit commit;
    commit.add(a);
    commit.add(b);
    commit.rename_added();
    commit.keep();
  }
  EXPECT_TRUE(std::filesystem::exists(dir_ / "a.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "b.csv"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 2);
}

TEST_F(OutputCommitTest, ARunThatFailsAfterTheRenamesLeavesNoFinalName) {
  {
    AtomicFile a(dir_ / "a.csv");
    a.stream() << "a\n";
    OutputCommit commit;
    commit.add(a);
    commit.rename_added();
    EXPECT_TRUE(std::filesystem::exists(dir_ / "a.csv"));
    // Not kept: the run failed after (e.g. its summary could not be written).
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

TEST_F(OutputCommitTest, AFailedRenameUndoesTheOnesBefore) {
  // b.csv cannot take the place of a directory holding a file.
  std::filesystem::create_directories(dir_ / "b.csv");
  std::ofstream(dir_ / "b.csv" / "keep") << "x";
  {
    AtomicFile a(dir_ / "a.csv");
    AtomicFile b(dir_ / "b.csv");
    AtomicFile c(dir_ / "c.csv");
    OutputCommit commit;
    commit.add(a);
    commit.add(b);
    commit.add(c);
    try {
      commit.rename_added();
      FAIL() << "a file was renamed over a directory";
    } catch (const RunError& error) {
      EXPECT_NE(std::string(error.what())
                    .find("cannot rename " + b.temporary().string() + " into place: "),
                std::string::npos)
          << error.what();
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "a.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "c.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "b.csv" / "keep"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 1);
}

TEST_F(OutputCommitTest, AMissingFileOfTheNetworkHalfIsNamed) {
  OutputCommit commit;
  try {
    commit.add(dir_ / "packets.csv.partial-1", dir_ / "packets.csv");
    FAIL() << "a missing file was accepted";
  } catch (const RunError& error) {
    EXPECT_EQ(std::string(error.what()), "cannot commit " + (dir_ / "packets.csv").string() + ": " +
                                             (dir_ / "packets.csv.partial-1").string() +
                                             " is missing");
  }
}

}  // namespace
}  // namespace swarmnet
