// The MAC's interface queue: a bounded FIFO whose packets expire after a maximum delay (ns-3's
// WifiMacQueue: 500 packets, 500 ms). As in ns-3, the packet taken out for an exchange keeps its
// place until released: ns-3 keeps a unicast MPDU in its queue until the exchange ends
// (acknowledged or dropped) and a group-addressed one until it goes on the air.
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

  // False (and nothing queued) when the queue is full().
  bool push(Packet packet, NodeId next_hop, SimTime now);
  // The oldest packet that has not waited longer than max_delay; expired ones met on the way are
  // removed and passed to `expired`. The packet returned keeps its place until release().
  std::optional<Item> pop(SimTime now, const std::function<void(const Item&)>& expired);
  // Frees the place of the packet last popped (a no-op when it is free already).
  void release() { place_held_ = false; }
  // Removes every packet that has waited longer than max_delay (the queue is in arrival order,
  // so they lead it) and returns them, oldest first. ns-3's WifiMacQueue does this when a packet
  // arrives at a full queue, before it refuses one.
  std::vector<Item> take_expired(SimTime now);

  // Whether a packet queued at `enqueued_at` has waited longer than max_delay at `now`.
  [[nodiscard]] bool outlived(SimTime enqueued_at, SimTime now) const {
    return now - enqueued_at > max_delay_;
  }
  // Whether the packet last popped still holds its place (not yet released).
  [[nodiscard]] bool holds_place() const { return place_held_; }
  [[nodiscard]] std::size_t size() const { return items_.size(); }
  [[nodiscard]] bool empty() const { return items_.empty(); }
  // `limit` places taken, by waiting packets and the popped one not yet released.
  [[nodiscard]] bool full() const { return items_.size() + (place_held_ ? 1U : 0U) >= limit_; }

 private:
  std::size_t limit_;
  SimTime max_delay_;
  std::deque<Item> items_;
  bool place_held_ = false;
};

}  // namespace swarmnet::dcf80211
