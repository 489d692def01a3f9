// A run's outputs put under their final names together, once the whole run has succeeded: each
// is finished (written and synced) under its temporary name first, so that a full disk or any
// other failure before the renames leaves no output under a final name. If a rename fails, or
// the run fails after the renames began, the names already made are removed again; temporary
// files not renamed are removed too.
#pragma once

#include <filesystem>
#include <vector>

#include "outputs/atomic_file.hpp"

namespace swarmnet {

class OutputCommit {
 public:
  OutputCommit() = default;
  OutputCommit(const OutputCommit&) = delete;
  OutputCommit& operator=(const OutputCommit&) = delete;
  OutputCommit(OutputCommit&&) = delete;
  OutputCommit& operator=(OutputCommit&&) = delete;
  // Unless keep() was called: removes the final names made and the temporary files not renamed.
  ~OutputCommit();

  // Finishes `file` (RunError with the system's reason when a write failed) and takes over its
  // temporary file.
  void add(AtomicFile& file);
  // A file another process finished (the network half's traces) under `temporary`. Throws
  // RunError naming it when it is missing.
  void add(const std::filesystem::path& temporary, const std::filesystem::path& final_path);
  // Renames what was added since the last call, in the order added. Throws RunError naming the
  // file and the system's reason.
  void rename_added();
  // The run succeeded: what was renamed stays.
  void keep() { kept_ = true; }

 private:
  struct Entry {
    std::filesystem::path temporary;
    std::filesystem::path final_path;
  };
  std::vector<Entry> added_;
  std::vector<Entry> renamed_;
  bool kept_ = false;
};

}  // namespace swarmnet
