// One node's ARP cache, as ns-3.37's ArpCache keeps it (src/internet/model/arp-cache.cc): an
// entry per neighbour address, in one of the states alive, wait-reply or dead, each with its
// timeout since the entry was last seen; a pending queue of packets per wait-reply entry; and
// one wait-reply timer for the whole cache, not one per entry.
//
// The cache holds state and answers questions; the protocol around it (network/arp.hpp) sends
// the requests and replies and hands queued packets on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>

#include "network/network_settings.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class ArpCache {
 public:
  enum class State : std::uint8_t { alive, wait_reply, dead };

  struct Entry {
    State state = State::alive;
    SimTime last_seen{};
    std::uint32_t retries = 0;
    std::deque<Packet> pending;  // oldest first
  };

  // What a send to a neighbour must do (ArpL3Protocol::Lookup).
  enum class Lookup : std::uint8_t {
    send,             // alive and unexpired: hand the packet to the MAC now
    request,          // no entry, or an expired one: the packet is queued, send a request
    queued,           // a request is outstanding: the packet joined the pending queue
    drop_queue_full,  // a request is outstanding and the pending queue is full
    drop_dead,        // the neighbour did not answer recently: the packet is dropped
  };

  explicit ArpCache(const ArpTimings& timings) : timings_(timings) {}

  // Looks `neighbor` up for `packet` at `now`; queues the packet where Lookup says so. A
  // `request` result also means the wait-reply timer must run (see timer_needed()).
  Lookup lookup(NodeId neighbor, Packet& packet, SimTime now);

  // A reply from `neighbor` arrived. Returns the packets it releases, oldest first, when its entry
  // was waiting (the entry becomes alive); nullopt when no entry waited for it (ns-3 drops such a
  // reply).
  std::optional<std::deque<Packet>> reply_received(NodeId neighbor, SimTime now);

  // The cache's wait-reply timer fired (ArpCache::HandleWaitReplyTimeout): every waiting entry
  // with retries left counts a retry and is listed in `retry`; the others die (listed in `died`)
  // and their pending packets go to `dropped`. Entries are visited in address order.
  struct Timeout {
    std::deque<NodeId> retry;
    std::deque<NodeId> died;
    std::deque<Packet> dropped;
  };
  Timeout wait_reply_timeout(SimTime now);

  // True when an entry waits for a reply and the cache-wide timer is not yet running; the
  // caller starts it and calls timer_started().
  [[nodiscard]] bool timer_needed() const { return waiting_ > 0 && !timer_running_; }
  void timer_started() { timer_running_ = true; }

  // Whether `neighbor` has an alive entry that has not expired (what ns-3's AODV asks of it).
  [[nodiscard]] bool resolved(NodeId neighbor, SimTime now) const;
  [[nodiscard]] const Entry* find(NodeId neighbor) const;
  [[nodiscard]] const ArpTimings& timings() const { return timings_; }

 private:
  [[nodiscard]] SimTime timeout(State state) const;
  [[nodiscard]] bool expired(const Entry& entry, SimTime now) const;
  void mark_wait_reply(Entry& entry, Packet& packet, SimTime now);

  ArpTimings timings_;
  std::map<NodeId, Entry> entries_;  // ordered: the timer visits entries in address order, as ns-3
  std::size_t waiting_ = 0;          // entries in wait_reply
  bool timer_running_ = false;
};

}  // namespace swarmnet
