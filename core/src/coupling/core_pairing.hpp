// Keeps a strict run's two halves on one core. In strict sync the halves take turns: one
// computes while the other waits, so one core is all a run can use, and on one core a hand-over
// is a same-core wake-up and switch (a few µs) instead of waking an idle core (on the 2-core
// development VM about 16 µs of CPU and 23 µs of wall time, docs/performance.md, "The hand-over").
// A sweep's runs then each take a core instead of four halves chasing each other over two.
//
// The pair is pinned to the core the robot half runs on. Every period (about 100 ms) the robot
// half reads how long both threads ran (/proc/.../schedstat): a pinned pair alone on its core
// runs nearly all the time (one half or the other), so one that ran less than three quarters of
// the period shares its core with other work and is set free, for the kernel's balancer to move;
// a free pair that ran more than nine tenths of the period has a core to itself and is pinned
// again where the robot half then runs. A free pair on a crowded machine stays free. Placement
// only ever changes how fast a run goes, never what it computes.
#pragma once

#include <sched.h>
#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <optional>

namespace swarmnet {

// A thread of some process: the network half's, to be kept beside the robot half.
struct ThreadId {
  pid_t process = 0;
  pid_t thread = 0;
};

class CorePairing {
 public:
  static constexpr std::chrono::milliseconds kPeriod{100};
  // Shares of a period in which one half or the other ran.
  static constexpr double kFreeBelow = 0.75;
  static constexpr double kPinAbove = 0.90;

  // Pins the calling thread (the robot half) and `network` to the core the caller runs on.
  // Does nothing when the caller may use only one CPU or the kernel refuses.
  explicit CorePairing(ThreadId network);
  CorePairing(const CorePairing&) = delete;
  CorePairing& operator=(const CorePairing&) = delete;
  CorePairing(CorePairing&&) = delete;
  CorePairing& operator=(CorePairing&&) = delete;
  // Gives the calling thread its CPU mask back (writing outputs afterwards is not pinned).
  ~CorePairing();

  // Once per step: every period, re-decides from how long the pair waited for its core.
  void tick(std::chrono::steady_clock::time_point now) {
    if (active_ && now >= next_look_) look(now);
  }

  [[nodiscard]] bool pinned() const { return pinned_; }

  // The CPU time a thread has run so far (the first field of its schedstat); nullopt when
  // unreadable (a thread that ended, a kernel without schedstats).
  static std::optional<std::chrono::nanoseconds> run_time(ThreadId thread);

 private:
  void look(std::chrono::steady_clock::time_point now);
  bool pin_to(int cpu);
  void set_free();

  ThreadId robot_{};
  ThreadId network_{};
  cpu_set_t allowed_{};  // the robot thread's mask before pairing, which it gets back
  bool active_ = false;
  bool pinned_ = false;
  std::chrono::steady_clock::time_point last_look_{};
  std::chrono::steady_clock::time_point next_look_{};
  std::chrono::nanoseconds last_run_{0};
  std::uint32_t jitter_ = 0;  // spreads the periods of runs started together
};

}  // namespace swarmnet
