// A cache of (node, id) pairs seen recently, each forgotten `lifetime` after it was first seen
// (ns-3's aodv-id-cache). Used for RREQ ids (RFC 3561 section 6.5: a node discards a RREQ it has
// already processed, identified by originator and RREQ id, for PATH_DISCOVERY_TIME) and, through
// DuplicateDetection, for broadcast data packets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <utility>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::aodv {

class IdCache {
 public:
  explicit IdCache(SimTime lifetime) : lifetime_(lifetime) {}

  // True if (node, id) was seen in the last `lifetime`; otherwise records it and returns false.
  bool is_duplicate(NodeId node, std::uint64_t id, SimTime now);
  [[nodiscard]] bool contains(NodeId node, std::uint64_t id, SimTime now) const;
  // Forgets pairs older than `lifetime`.
  void purge(SimTime now);
  [[nodiscard]] std::size_t size() const { return expiry_.size(); }
  [[nodiscard]] SimTime lifetime() const { return lifetime_; }

 private:
  using Key = std::pair<NodeId, std::uint64_t>;
  SimTime lifetime_;
  std::map<Key, SimTime> expiry_;
  std::deque<std::pair<SimTime, Key>> order_;  // insertion order == expiry order
};

}  // namespace swarmnet::aodv
