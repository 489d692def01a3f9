// Services the network kernel gives every per-node plugin (MAC, routing): the node's identity,
// the simulated clock and cancellable timers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

using TimerId = std::uint64_t;
inline constexpr TimerId kNoTimer = 0;

class NodeContext {
 public:
  [[nodiscard]] virtual NodeId node() const = 0;
  [[nodiscard]] virtual std::size_t node_count() const = 0;
  [[nodiscard]] virtual SimTime now() const = 0;
  [[nodiscard]] virtual Vec2 position() const = 0;

  // Runs `callback` after `delay` (>= 0) of simulated time. Events at the same instant run in
  // the order they were scheduled.
  virtual TimerId schedule(SimTime delay, std::function<void()> callback) = 0;
  // Cancels a pending timer; cancelling a fired, cancelled or kNoTimer id does nothing.
  virtual void cancel(TimerId timer) = 0;

  // Adds to a named counter of this layer; summary.json sums it over nodes under mac.* or
  // routing.* (e.g. "retries", "control_rreq").
  virtual void count(std::string_view counter, std::uint64_t amount = 1) = 0;

 protected:
  ~NodeContext() = default;
};

}  // namespace swarmnet
