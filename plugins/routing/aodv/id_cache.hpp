// A cache of (node, id) pairs seen recently, each forgotten `lifetime` after it was first seen
// (ns-3's aodv-id-cache). Used for RREQ ids (RFC 3561 section 6.5: a node discards a RREQ it has
// already processed, identified by originator and RREQ id, for PATH_DISCOVERY_TIME) and, through
// DuplicateDetection, for broadcast data packets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <unordered_map>
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
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      // splitmix64's finalizer over node and id (ids are small consecutive numbers per node).
      std::uint64_t x = (static_cast<std::uint64_t>(key.first) << 40U) ^ key.second;
      x ^= x >> 30U;
      x *= 0xbf58476d1ce4e5b9ULL;
      x ^= x >> 27U;
      x *= 0x94d049bb133111ebULL;
      x ^= x >> 31U;
      return static_cast<std::size_t>(x);
    }
  };
  SimTime lifetime_;
  // Looked up, never walked: a hash table's order reaches no result.
  std::unordered_map<Key, SimTime, KeyHash> expiry_;
  std::deque<std::pair<SimTime, Key>> order_;  // insertion order == expiry order
};

}  // namespace swarmnet::aodv
