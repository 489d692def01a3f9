// How a blocked ring or socket operation waits: spin briefly (cheap when the peer answers within
// microseconds), yield the core a few times (on a busy 2-core machine the peer may need it),
// then sleep on a futex or in poll() so that an idle half uses no CPU.
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
  std::uint32_t yield_iterations = 8;  // sched_yield() calls before sleeping
  std::chrono::nanoseconds sleep_slice = std::chrono::milliseconds(20);  // re-check interval
  std::chrono::nanoseconds timeout = std::chrono::seconds(60);           // give up: the peer hangs
  // Called between sleep slices; returns false when the peer is known to be gone.
  std::function<bool()> peer_alive;
  // A count that grows while the peer works (its CPU time). When set, a wait gives up only
  // after `timeout` during which the count stood still: a peer computing a long step (a network
  // half in a route-request storm at thousands of robots) is slow, not hung. Called once a
  // timeout, not in the spin.
  std::function<std::uint64_t()> peer_work;
};

// When a wait under a policy is over: `timeout` after it began, pushed back by another `timeout`
// each time the peer's work count (WaitPolicy::peer_work) has grown since the last look. The
// clock only bounds waiting; it never reaches a result.
class WaitDeadline {
 public:
  explicit WaitDeadline(const WaitPolicy& policy)
      : policy_(policy),
        deadline_(std::chrono::steady_clock::now() + policy.timeout),
        work_(policy.peer_work ? policy.peer_work() : 0) {}

  [[nodiscard]] bool passed(std::chrono::steady_clock::time_point now) {
    if (now < deadline_) return false;
    if (!policy_.peer_work) return true;
    const std::uint64_t work = policy_.peer_work();
    if (work == work_) return true;
    work_ = work;
    deadline_ = now + policy_.timeout;
    return false;
  }

 private:
  const WaitPolicy& policy_;
  std::chrono::steady_clock::time_point deadline_;
  std::uint64_t work_;
};

// A hint to the CPU that this thread is spinning (eases the sibling hyperthread).
inline void cpu_relax() { __builtin_ia32_pause(); }

// The first two stages of a wait under `policy`, shared by the ring and the socket transports:
// polls `ready` (true once the wait is over) for the spin time, then yields the core
// yield_iterations times, polling after each. Returns whether `ready` answered true; if not, the
// caller sleeps in its own way (a futex, poll()). The clock only bounds the spinning.
template <typename Ready>
bool spin_then_yield(const WaitPolicy& policy, Ready&& ready) {
  if (ready()) return true;
  const auto spin_until = std::chrono::steady_clock::now() + policy.spin_time;
  for (std::uint32_t i = 1;; ++i) {
    cpu_relax();
    if (ready()) return true;
    // The clock is read every 32 polls: a pause lasts only 10 to 140 cycles.
    if (i % 32 == 0 && std::chrono::steady_clock::now() >= spin_until) break;
  }
  // On a machine with fewer free cores than runnable threads, spinning only delays the peer we
  // wait for: give the core away a few times before sleeping.
  for (std::uint32_t i = 0; i < policy.yield_iterations; ++i) {
    sched_yield();
    if (ready()) return true;
  }
  return false;
}

}  // namespace swarmnet
