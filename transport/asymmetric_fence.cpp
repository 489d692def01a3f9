#include "asymmetric_fence.hpp"

#include <linux/membarrier.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <mutex>

namespace swarmnet {

namespace {

long membarrier(int command) { return syscall(SYS_membarrier, command, 0U, 0); }

bool register_this_process() {
  const long supported = membarrier(MEMBARRIER_CMD_QUERY);
  if (supported < 0 || (supported & MEMBARRIER_CMD_GLOBAL_EXPEDITED) == 0 ||
      (supported & MEMBARRIER_CMD_REGISTER_GLOBAL_EXPEDITED) == 0) {
    return false;
  }
  return membarrier(MEMBARRIER_CMD_REGISTER_GLOBAL_EXPEDITED) == 0 &&
         membarrier(MEMBARRIER_CMD_GLOBAL_EXPEDITED) == 0;
}

}  // namespace

bool asymmetric_fences_available() {
  // Keyed by process id, so that a forked child asks (and registers) for itself rather than
  // trusting its parent's answer; registering twice is harmless.
  static std::mutex mutex;
  static pid_t answered_for = 0;
  static bool available = false;
  const std::lock_guard lock(mutex);
  if (answered_for != ::getpid()) {
    available = register_this_process();
    answered_for = ::getpid();
  }
  return available;
}

void heavy_fence() {
  // Cannot fail once asymmetric_fences_available() saw it succeed (the kernel refuses only
  // unknown commands). Were it to, a sleeper could miss one wake-up and would find the news at
  // the end of its sleep slice: late, never hung.
  membarrier(MEMBARRIER_CMD_GLOBAL_EXPEDITED);
}

}  // namespace swarmnet
