// Duplicate detection for flooding: the (originator, sequence) pairs seen most recently.
//
// Bounded to `capacity` entries; when full, inserting evicts the entry inserted first (FIFO, not
// LRU: seeing a duplicate does not refresh an entry). A pair evicted and then received again is
// taken for new and relayed once more, so the capacity should exceed the number of distinct
// packets a node can see while copies of one packet are still travelling.
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

#include "swarmnet/ids.hpp"

namespace swarmnet::flooding {

class DuplicateCache {
 public:
  explicit DuplicateCache(std::size_t capacity);

  // Records the pair; returns true if it was not in the cache (a packet seen for the first time).
  bool insert(NodeId originator, std::uint32_t sequence);
  [[nodiscard]] bool contains(NodeId originator, std::uint32_t sequence) const;
  [[nodiscard]] std::size_t size() const { return keys_.size(); }
  [[nodiscard]] std::size_t capacity() const { return order_.size(); }

 private:
  static std::uint64_t key(NodeId originator, std::uint32_t sequence) {
    return (static_cast<std::uint64_t>(originator) << 32U) | sequence;
  }

  std::set<std::uint64_t> keys_;
  std::vector<std::uint64_t> order_;  // ring of keys in insertion order
  std::size_t next_ = 0;              // ring slot the next insertion takes (the oldest when full)
};

}  // namespace swarmnet::flooding
