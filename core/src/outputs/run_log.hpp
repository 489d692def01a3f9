// run.log: what was run with which plugins, how far it got, and how it ended. Every line is
// written to the file at once (run.log.partial-PID until the run ends), so that a run killed
// with SIGKILL leaves a log saying how far it got. Room for the log is reserved on disk when it
// is created, so that a run failing on a full disk can still say why.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>

namespace swarmnet {

class RunLog {
 public:
  // Creates DIR/run.log.partial-PID for `path` (DIR/run.log) and reserves room for it. Throws
  // RunError naming the file and the system's reason when it cannot.
  explicit RunLog(std::filesystem::path path);
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;
  RunLog(RunLog&&) = delete;
  RunLog& operator=(RunLog&&) = delete;
  // Closes the file; one not committed stays under its temporary name (it says how far the run
  // got; the next run into the directory or `swarmnet clean` removes it).
  ~RunLog();

  // Appends a line. Throws RunError (with the system's reason) when it cannot be written.
  void line(const std::string& text);
  // The last line of a run that failed: never throws; shortened if it does not fit in the room
  // left (a full disk), and committed under the final name.
  void fail(const std::string& text) noexcept;
  // A progress line ("at step N of M, T s simulated") now and then: after 1 s of wall time, then
  // at doubling intervals up to one a minute. Reads the wall clock for that only.
  void progress(std::uint64_t step, std::uint64_t steps, double step_s);
  // Syncs the log and renames it to its final name. Lines may still follow (a failure after it).
  void commit();

  [[nodiscard]] const std::filesystem::path& temporary() const { return temporary_; }

 private:
  // Reserves room up to `end` bytes (beyond the file's end, which stays where the text ends).
  bool reserve(off_t end);
  bool write_at_end(const std::string& text);

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  off_t length_ = 0;    // bytes written
  off_t reserved_ = 0;  // bytes of room held on disk
  bool committed_ = false;
  std::chrono::steady_clock::time_point next_progress_;
  std::chrono::seconds progress_interval_{1};
};

}  // namespace swarmnet
