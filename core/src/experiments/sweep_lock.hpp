// One sweep per directory: an exclusive lock on DIR/.sweep.lock (holding the holder's pid) for
// as long as a sweep runs into DIR, or submits it to Slurm.
#pragma once

#include <filesystem>

namespace swarmnet {

// Holds an exclusive lock on the sweep directory for this object's life: a second sweep into
// the same directory (an immediate resume while the first still runs) is refused, not run into
// the same run directories at the same time.
class SweepLock {
 public:
  // Throws RunError "another sweep (pid N) is running into DIR; ..." when the lock is held.
  explicit SweepLock(const std::filesystem::path& out);
  ~SweepLock();
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace swarmnet
