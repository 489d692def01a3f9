// How a blocked ring or socket operation waits: spin briefly (cheap when the peer answers within
// microseconds), yield the core a few times (on a busy 2-core machine the peer may need it),
// then sleep on a futex or in poll() so that an idle half uses no CPU.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>

namespace swarmnet {

struct WaitPolicy {
  std::uint32_t spin_iterations = 256;  // polls before yielding; 0: none
  std::uint32_t yield_iterations = 8;   // sched_yield() calls before sleeping
  std::chrono::nanoseconds sleep_slice = std::chrono::milliseconds(20);  // re-check interval
  std::chrono::nanoseconds timeout = std::chrono::seconds(60);           // give up: the peer hangs
  // Called between sleep slices; returns false when the peer is known to be gone.
  std::function<bool()> peer_alive;
};

}  // namespace swarmnet
