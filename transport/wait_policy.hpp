// How a blocked ring operation waits: spin briefly (cheap when the peer answers within
// microseconds), then sleep on a futex so that an idle half uses no CPU on a 2-core machine.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>

namespace swarmnet {

struct WaitPolicy {
  std::uint32_t spin_iterations =
      256;  // polls before sleeping (tens of microseconds); 0: sleep at once
  std::chrono::nanoseconds sleep_slice = std::chrono::milliseconds(20);  // re-check interval
  std::chrono::nanoseconds timeout = std::chrono::seconds(60);           // give up: the peer hangs
  // Called between sleep slices; returns false when the peer is known to be gone.
  std::function<bool()> peer_alive;
};

}  // namespace swarmnet
