#include "spin_conditions.hpp"

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <array>
#include <cstdio>

namespace swarmnet {

namespace {

// The fourth field of /proc/loadavg, "R/T": threads runnable now, out of all. 0 when unreadable
// (then only the CPU mask decides).
int runnable_threads() {
  const int fd = ::open("/proc/loadavg", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  std::array<char, 128> text{};
  const ssize_t got = ::read(fd, text.data(), text.size() - 1);
  ::close(fd);
  if (got <= 0) return 0;
  double one = 0;
  double five = 0;
  double fifteen = 0;
  int runnable = 0;
  int total = 0;
  if (std::sscanf(text.data(), "%lf %lf %lf %d/%d", &one, &five, &fifteen, &runnable, &total) !=
      5) {
    return 0;
  }
  return runnable;
}

}  // namespace

SpinConditions read_spin_conditions() {
  SpinConditions c;
  cpu_set_t mask;
  CPU_ZERO(&mask);
  c.usable_cpus = ::sched_getaffinity(0, sizeof mask, &mask) == 0 ? CPU_COUNT(&mask) : 1;
  c.runnable_threads = runnable_threads();
  return c;
}

bool spinning_can_pay(std::chrono::steady_clock::time_point now) {
  // Per thread: in one process the robot half and an in-process network half have their own
  // masks.
  thread_local std::chrono::steady_clock::time_point next_read{};
  thread_local bool pays = true;
  if (now >= next_read) {
    pays = spinning_pays_under(read_spin_conditions());
    next_read = now + kSpinConditionsRefresh;
  }
  return pays;
}

}  // namespace swarmnet
