// How a blocked ring or socket operation waits: spin briefly (cheap when the peer answers within
// microseconds), yield the core a few times (on a busy 2-core machine the peer may need it),
// then sleep on a futex or in poll() so that an idle half uses no CPU.
#pragma once

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
};

}  // namespace swarmnet
