// The MAC's interface queue: a bounded FIFO whose packets expire after a maximum delay (ns-3's
// WifiMacQueue: 500 packets, 500 ms).
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

#include "swarmnet/packet.hpp"

namespace swarmnet::dcf80211 {

class InterfaceQueue {
 public:
  struct Item {
    Packet packet;
    NodeId next_hop = kBroadcast;
    SimTime enqueued_at{};
  };

  InterfaceQueue(std::size_t limit, SimTime max_delay) : limit_(limit), max_delay_(max_delay) {}

  // False (and nothing queued) when the queue holds `limit` packets.
  bool push(Packet packet, NodeId next_hop, SimTime now);
  // The oldest packet that has not waited longer than max_delay; expired ones met on the way are
  // removed and passed to `expired`.
  std::optional<Item> pop(SimTime now, const std::function<void(const Item&)>& expired);
  // Removes every packet that has waited longer than max_delay (the queue is in arrival order,
  // so they lead it) and returns them, oldest first. ns-3's WifiMacQueue does this when a packet
  // arrives at a full queue, before it refuses one.
  std::vector<Item> take_expired(SimTime now);

  [[nodiscard]] std::size_t size() const { return items_.size(); }
  [[nodiscard]] bool empty() const { return items_.empty(); }
  // True when no packet may join: the queue holds `limit` packets, counting the one taken out
  // for an exchange still under way (`in_exchange`). ns-3's WifiMacQueue keeps an MPDU until its
  // exchange ends (acknowledged, or dropped), so it counts against MaxSize.
  [[nodiscard]] bool full(bool in_exchange) const {
    return items_.size() + (in_exchange ? 1U : 0U) >= limit_;
  }

 private:
  std::size_t limit_;
  SimTime max_delay_;
  std::deque<Item> items_;
};

}  // namespace swarmnet::dcf80211
