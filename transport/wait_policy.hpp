// How a blocked ring or socket operation waits: spin briefly when the peer lately answered within
// microseconds (wait_pace.hpp), yield the core a few times (on a busy 2-core machine, or one core
// shared with the peer, the peer may need it), then sleep on a futex or in poll() so that an idle
// half uses no CPU.
#pragma once

#include <sched.h>

#include <chrono>
#include <cstdint>
#include <functional>

namespace swarmnet {

struct WaitPolicy {
  // Polling before yielding, bounded by time rather than a count because a pause instruction
  // lasts 10 to 140 cycles depending on the CPU. Long enough to cover the peer's work on a small
  // step (a step exchange of hundreds of robots takes microseconds), short enough to be
  // negligible against a step that takes milliseconds.
  std::chrono::nanoseconds spin_time = std::chrono::microseconds(50);
  // The longest the peer may lately have taken to answer for a wait to spin at all (wait_pace.hpp):
  // about what a sleep and a wake-up cost in CPU, so spinning never costs more than sleeping.
  std::chrono::nanoseconds spin_worth = std::chrono::microseconds(10);
  std::uint32_t yield_iterations = 8;  // sched_yield() calls before sleeping
  std::chrono::nanoseconds sleep_slice = std::chrono::milliseconds(20);  // re-check interval
  std::chrono::nanoseconds timeout = std::chrono::seconds(60);           // give up: the peer hangs
  // Called between sleep slices; returns false when the peer is known to be gone.
  std::function<bool()> peer_alive;
  // The CPU time the peer has used so far. When set, a wait gives up only after a whole
  // `timeout` in which the peer used less than a tenth of it in CPU: a peer computing a long
  // step (a network half in a route-request storm at thousands of robots) is slow, not hung,
  // while two halves blocked on each other, which wake each sleep slice for microseconds, still
  // time out. Read only once a wait has slept a slice, never in the spin.
  std::function<std::chrono::nanoseconds()> peer_cpu;
};

// When a wait under a policy is over. Without peer_cpu: `timeout` after it began. With it: at the
// end of the first `timeout`-long window, counted from the first sleep slice, in which the peer
// used less than a tenth of the window in CPU; a peer that stops computing is thus found within
// two timeouts. The clocks only bound waiting; they never reach a result.
class WaitDeadline {
 public:
  explicit WaitDeadline(const WaitPolicy& policy)
      : policy_(policy), deadline_(std::chrono::steady_clock::now() + policy.timeout) {}
  explicit WaitDeadline(WaitPolicy&&) = delete;  // it keeps a reference: not to a temporary

  [[nodiscard]] bool passed(std::chrono::steady_clock::time_point now) {
    if (policy_.peer_cpu && !baseline_) {
      cpu_ = policy_.peer_cpu();  // lazily: most waits end within a slice
      baseline_ = true;
    }
    if (now < deadline_) return false;
    if (!policy_.peer_cpu) return true;
    const std::chrono::nanoseconds cpu = policy_.peer_cpu();
    if (cpu - cpu_ < policy_.timeout / 10) return true;  // a failed read (0) counts as no work
    cpu_ = cpu;
    deadline_ = now + policy_.timeout;
    return false;
  }

 private:
  const WaitPolicy& policy_;
  std::chrono::steady_clock::time_point deadline_;
  std::chrono::nanoseconds cpu_{0};
  bool baseline_ = false;
};

// A hint to the CPU that this thread is spinning (eases the sibling hyperthread).
inline void cpu_relax() { __builtin_ia32_pause(); }

// How one wait spins and yields before it sleeps (WaitPace chooses it per wait).
struct WaitPlan {
  std::chrono::nanoseconds spin_time{0};
  std::uint32_t yield_iterations = 0;
};

// The first two stages of a wait, shared by the ring and the socket transports: polls `ready`
// (true once the wait is over) for the plan's spin time, then yields the core yield_iterations
// times, polling after each. Returns whether `ready` answered true; if not, the caller sleeps in
// its own way (a futex, poll()). The clock only bounds the spinning.
template <typename Ready>
bool spin_then_yield(const WaitPlan& plan, std::chrono::steady_clock::time_point start,
                     Ready&& ready) {
  if (ready()) return true;
  const auto spin_until = start + plan.spin_time;
  for (std::uint32_t i = 1; plan.spin_time.count() > 0; ++i) {
    cpu_relax();
    if (ready()) return true;
    // The clock is read every 32 polls: a pause lasts only 10 to 140 cycles.
    if (i % 32 == 0 && std::chrono::steady_clock::now() >= spin_until) break;
  }
  // Where the peer shares this core, or more threads are runnable than there are cores, the peer
  // may be waiting for this one: give the core away a few times before sleeping.
  for (std::uint32_t i = 0; i < plan.yield_iterations; ++i) {
    sched_yield();
    if (ready()) return true;
  }
  return false;
}

}  // namespace swarmnet
