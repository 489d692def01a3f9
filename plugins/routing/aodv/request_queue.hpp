// Data packets waiting for a route (RFC 3561 section 6.3, ns-3's aodv-rqueue).
//
// Bounded to `max_len` packets: a packet arriving at a full queue pushes the oldest one out
// (dropped as queue_full, as ns-3 does). A packet that waited longer than `max_time` is dropped as
// buffer_timeout when the queue is next touched (purge() or any other call). Drops go through
// the callback given at construction; packets leave in arrival order.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <vector>

#include "swarmnet/packet.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::aodv {

class RequestQueue {
 public:
  using DropCallback = std::function<void(const Packet&, DropReason)>;

  RequestQueue(std::size_t max_len, SimTime max_time, DropCallback drop);

  // Buffers `packet` for its destination; returns false (and keeps nothing) if a packet with the
  // same uid is already waiting.
  bool enqueue(Packet packet, SimTime now);
  // Removes and returns every packet waiting for `destination`, in arrival order.
  std::vector<Packet> take(NodeId destination, SimTime now);
  // Drops every packet waiting for `destination` with `reason`.
  void drop_destination(NodeId destination, DropReason reason, SimTime now);
  // Drops packets that waited too long.
  void purge(SimTime now);

  [[nodiscard]] bool has(NodeId destination) const;
  [[nodiscard]] std::size_t size() const { return entries_.size(); }
  [[nodiscard]] std::size_t max_len() const { return max_len_; }
  // When the oldest packet expires, or kTimeNever if the queue is empty.
  [[nodiscard]] SimTime next_expiry() const;

 private:
  struct Entry {
    Packet packet;
    SimTime expires;
  };

  std::size_t max_len_;
  SimTime max_time_;
  DropCallback drop_;
  std::deque<Entry> entries_;  // arrival order == expiry order
};

}  // namespace swarmnet::aodv
