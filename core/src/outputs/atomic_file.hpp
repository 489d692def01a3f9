// An output file that appears under its name only when complete: written to a temporary name in
// the same directory and renamed by commit(). A run that fails or is killed leaves no truncated
// file that looks whole; a file not committed is removed when the object goes away.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace swarmnet {

class AtomicFile {
 public:
  // Throws RunError naming the path when the temporary file cannot be created.
  explicit AtomicFile(std::filesystem::path path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&&) = delete;
  AtomicFile& operator=(AtomicFile&&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return stream_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  // Flushes and syncs to disk under the temporary name. Throws RunError with the system's reason
  // (e.g. "No space left on device") if any write failed. No more writes after it.
  void finish();
  // finish() (if not done yet), then renames to the final name.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what);

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::vector<char> buffer_;
  std::ofstream stream_;
  bool finished_ = false;
  bool committed_ = false;
};

// Writes `text` to `path` atomically.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace swarmnet
