#include "coupling/core_pairing.hpp"

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <string>

namespace swarmnet {

namespace {

pid_t this_thread() { return static_cast<pid_t>(::syscall(SYS_gettid)); }

}  // namespace

std::optional<std::chrono::nanoseconds> CorePairing::run_time(ThreadId thread) {
  const std::string path = "/proc/" + std::to_string(thread.process) + "/task/" +
                           std::to_string(thread.thread) + "/schedstat";
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::array<char, 96> text{};
  const ssize_t got = ::read(fd, text.data(), text.size() - 1);
  ::close(fd);
  unsigned long long running_ns = 0;
  unsigned long long waiting_ns = 0;
  if (got <= 0 || std::sscanf(text.data(), "%llu %llu", &running_ns, &waiting_ns) != 2) {
    return std::nullopt;
  }
  return std::chrono::nanoseconds(static_cast<std::int64_t>(running_ns));
}

CorePairing::CorePairing(ThreadId network) : robot_{::getpid(), this_thread()}, network_(network) {
  CPU_ZERO(&allowed_);
  if (network_.thread <= 0 || ::sched_getaffinity(0, sizeof allowed_, &allowed_) != 0 ||
      CPU_COUNT(&allowed_) < 2) {
    return;
  }
  const auto robot_wait = run_time(robot_);
  const auto network_wait = run_time(network_);
  if (!robot_wait || !network_wait) return;
  last_run_ = *robot_wait + *network_wait;
  active_ = true;
  // Not the simulation's random streams: placement never touches a result.
  jitter_ = static_cast<std::uint32_t>(robot_.thread) * 2654435761U;
  const auto now = std::chrono::steady_clock::now();
  last_look_ = now;
  next_look_ = now + kPeriod;
  if (!pin_to(::sched_getcpu())) {
    set_free();
    active_ = false;
  }
}

CorePairing::~CorePairing() {
  if (active_) ::sched_setaffinity(0, sizeof allowed_, &allowed_);
}

bool CorePairing::pin_to(int cpu) {
  if (cpu < 0 || !CPU_ISSET(cpu, &allowed_)) return false;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(cpu, &one);
  // The network half first: when it is pinned, the robot half follows it there at once.
  if (::sched_setaffinity(network_.thread, sizeof one, &one) != 0) return false;
  if (::sched_setaffinity(0, sizeof one, &one) != 0) return false;
  pinned_ = true;
  return true;
}

void CorePairing::set_free() {
  ::sched_setaffinity(network_.thread, sizeof allowed_, &allowed_);
  ::sched_setaffinity(0, sizeof allowed_, &allowed_);
  pinned_ = false;
}

void CorePairing::look(std::chrono::steady_clock::time_point now) {
  const auto robot = run_time(robot_);
  const auto network = run_time(network_);
  if (!robot || !network) {  // the network half is gone, or no schedstats: stop looking
    active_ = false;
    return;
  }
  const std::chrono::nanoseconds ran = *robot + *network;
  const double share = std::chrono::duration<double>(ran - last_run_).count() /
                       std::chrono::duration<double>(now - last_look_).count();
  last_run_ = ran;
  last_look_ = now;
  // 100 to 150 ms, so that two runs started together do not move in step.
  jitter_ = jitter_ * 1664525U + 1013904223U;
  next_look_ = now + kPeriod + kPeriod * (jitter_ >> 16U) / 131072U;
  if (pinned_ && share < kFreeBelow) {
    set_free();
  } else if (!pinned_ && share > kPinAbove) {
    pin_to(::sched_getcpu());
  }
}

}  // namespace swarmnet
