#include "coupling/memory_budget.hpp"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "outputs/run_error.hpp"

namespace swarmnet {

namespace {

// VmData of this process (what RLIMIT_DATA counts), in bytes.
std::uint64_t data_segment_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmData:", 0) == 0) return std::stoull(line.substr(7)) * 1024U;  // in kB
  }
  return 0;
}

}  // namespace

std::uint64_t default_memory_budget() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return std::uint64_t{4} << 30U;  // unknown: 4 GiB
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 2;
}

bool kernel_memory_limit_available() {
#if defined(__SANITIZE_ADDRESS__)
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

void limit_process_memory(const MemoryBudget& budget, std::uint64_t reserve) {
  if (!kernel_memory_limit_available()) return;
  const std::uint64_t limit = data_segment_bytes() + budget.bytes + reserve;
  rlimit current{};
  ::getrlimit(RLIMIT_DATA, &current);
  rlimit wanted{limit, current.rlim_max};
  if (current.rlim_max != RLIM_INFINITY && limit > current.rlim_max)
    wanted.rlim_cur = current.rlim_max;
  if (::setrlimit(RLIMIT_DATA, &wanted) != 0) {
    throw RunError("cannot limit this process's memory to " + describe_bytes(limit) + ": " +
                   std::strerror(errno));
  }
}

std::uint64_t heap_in_use_bytes() {
  const struct mallinfo2 info = ::mallinfo2();
  return info.uordblks + info.hblkhd;
}

std::uint64_t return_free_memory() {
  ::malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  std::uint64_t size = 0;
  std::uint64_t resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

std::string describe_bytes(std::uint64_t bytes) {
  char text[32];
  if (bytes >= (std::uint64_t{1} << 30U)) {
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1U << 30U));
  } else {
    std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1U << 20U));
  }
  return text;
}

}  // namespace swarmnet
