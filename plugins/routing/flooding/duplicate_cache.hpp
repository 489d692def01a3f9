// Duplicate detection for flooding: the (originator, sequence) pairs seen most recently.
//
// Bounded to `capacity` entries; when full, inserting evicts the entry inserted first (FIFO, not
// LRU: seeing a duplicate does not refresh an entry). A pair evicted and then received again is
// taken for new and relayed once more, so the capacity should exceed the number of distinct
// packets a node can see while copies of one packet are still travelling.
//
// Storage: a ring of keys in insertion order and an open-addressing hash set (linear probing,
// at most half full, backward-shift deletion) over them. Both grow with what the cache holds, up
// to `capacity`: a node that hears few packets costs a few hundred bytes, not 24 x capacity
// (a swarm of 100,000 nodes with the limit at 10^7 would otherwise ask for terabytes up front).
// Every node looks its cache up once per copy it hears, so this is on the flooding hot path; a tree
// set cost a cache miss per level.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarmnet/ids.hpp"

namespace swarmnet::flooding {

class DuplicateCache {
 public:
  explicit DuplicateCache(std::size_t capacity);

  // Records the pair; returns true if it was not in the cache (a packet seen for the first time).
  bool insert(NodeId originator, std::uint32_t sequence);
  [[nodiscard]] bool contains(NodeId originator, std::uint32_t sequence) const;
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] std::size_t capacity() const { return capacity_; }
  // Bytes the cache holds now (its two tables), for tests of its growth.
  [[nodiscard]] std::size_t allocated_bytes() const {
    return (order_.capacity() + slots_.capacity()) * sizeof(std::uint64_t);
  }

 private:
  // A slot holding kEmpty is free; the one key equal to kEmpty is tracked by has_empty_key_.
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  static std::uint64_t key(NodeId originator, std::uint32_t sequence) {
    return (static_cast<std::uint64_t>(originator) << 32U) | sequence;
  }
  [[nodiscard]] std::size_t home(std::uint64_t k) const;
  // The slot holding `k`, or the free slot where it would go.
  [[nodiscard]] std::size_t find_slot(std::uint64_t k) const;
  bool contains_key(std::uint64_t k) const;
  void add_key(std::uint64_t k);
  void erase_key(std::uint64_t k);
  void grow_slots();  // doubles the hash set and re-inserts every key

  // A small table to start with; it doubles as the cache fills.
  static constexpr std::size_t kInitialSlots = 16;

  std::size_t capacity_;
  std::vector<std::uint64_t> order_;  // keys in insertion order; a ring once capacity_ long
  std::size_t next_ = 0;              // once full: the ring slot of the oldest key, taken next
  std::size_t size_ = 0;
  std::vector<std::uint64_t> slots_;  // hash set; size a power of two >= 2 x capacity
  std::size_t mask_ = 0;
  bool has_empty_key_ = false;
};

}  // namespace swarmnet::flooding
