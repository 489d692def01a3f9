// An output file that appears under its name only when complete: written to a temporary name in
// the same directory and renamed by commit() (or, for a run's outputs, by OutputCommit once the
// whole run succeeded). A run that fails or is killed leaves no truncated file that looks whole;
// a file not committed or handed over is removed when the object goes away.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

#include "outputs/file_buffer.hpp"

namespace swarmnet {

class AtomicFile {
 public:
  // Throws RunError naming the path and the system's reason when the temporary file cannot be
  // created.
  explicit AtomicFile(std::filesystem::path path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&&) = delete;
  AtomicFile& operator=(AtomicFile&&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return stream_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  // NAME.partial-PID beside the final name.
  [[nodiscard]] const std::filesystem::path& temporary() const { return temporary_; }

  // Writes what is buffered and syncs it to disk under the temporary name. Throws RunError with
  // the system's reason (e.g. "No space left on device") if any write failed. No more writes
  // after it.
  void finish();
  // finish() (if not done yet), then renames to the final name.
  void commit();
  // finish() (if not done yet); the temporary file is then someone else's to rename or remove
  // (OutputCommit, or the robot half for the network half's traces): it stays when this goes.
  void hand_over();

 private:
  [[noreturn]] void fail(const std::string& what, int error) const;
  void close_descriptor();

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  std::optional<FileBuffer> buffer_;
  std::ostream stream_{nullptr};
  bool finished_ = false;
  bool kept_ = false;  // committed or handed over: not removed with the object
};

// Writes `text` to `path` atomically.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace swarmnet
