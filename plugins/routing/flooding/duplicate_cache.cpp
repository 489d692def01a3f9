#include "duplicate_cache.hpp"

#include <algorithm>

namespace swarmnet::flooding {

DuplicateCache::DuplicateCache(std::size_t capacity)
    : capacity_(std::max<std::size_t>(capacity, 1)),
      slots_(kInitialSlots, kEmpty),
      mask_(slots_.size() - 1) {}

void DuplicateCache::grow_slots() {
  std::vector<std::uint64_t> old(slots_.size() * 2, kEmpty);
  old.swap(slots_);
  mask_ = slots_.size() - 1;
  for (const std::uint64_t k : old) {
    if (k != kEmpty) slots_[find_slot(k)] = k;
  }
}

std::size_t DuplicateCache::home(std::uint64_t k) const {
  // Fibonacci hashing: sequences of one originator are consecutive, so mix the bits.
  return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ULL) >> 32U) & mask_;
}

std::size_t DuplicateCache::find_slot(std::uint64_t k) const {
  std::size_t i = home(k);
  while (slots_[i] != kEmpty && slots_[i] != k) i = (i + 1) & mask_;
  return i;
}

bool DuplicateCache::contains_key(std::uint64_t k) const {
  if (k == kEmpty) return has_empty_key_;
  return slots_[find_slot(k)] == k;
}

void DuplicateCache::add_key(std::uint64_t k) {
  if (k == kEmpty) {
    has_empty_key_ = true;
  } else {
    if (2 * (size_ + 1) > slots_.size()) grow_slots();  // at most half full
    slots_[find_slot(k)] = k;
  }
  ++size_;
}

void DuplicateCache::erase_key(std::uint64_t k) {
  --size_;
  if (k == kEmpty) {
    has_empty_key_ = false;
    return;
  }
  std::size_t hole = find_slot(k);
  slots_[hole] = kEmpty;
  // Backward-shift deletion: move later keys of the probe run into the hole when their home
  // position allows it, so lookups never stop early at the hole.
  for (std::size_t i = (hole + 1) & mask_; slots_[i] != kEmpty; i = (i + 1) & mask_) {
    const std::size_t h = home(slots_[i]);
    // The key at i may move to the hole if the hole lies cyclically in [h, i).
    const bool movable = ((i - h) & mask_) >= ((i - hole) & mask_);
    if (movable) {
      slots_[hole] = slots_[i];
      slots_[i] = kEmpty;
      hole = i;
    }
  }
}

bool DuplicateCache::insert(NodeId originator, std::uint32_t sequence) {
  const std::uint64_t k = key(originator, sequence);
  if (contains_key(k)) return false;
  if (order_.size() < capacity_) {  // still filling: the oldest is order_[0] when it is full
    add_key(k);
    order_.push_back(k);
    return true;
  }
  erase_key(order_[next_]);  // evict the oldest
  add_key(k);
  order_[next_] = k;
  next_ = (next_ + 1) % capacity_;
  return true;
}

bool DuplicateCache::contains(NodeId originator, std::uint32_t sequence) const {
  return contains_key(key(originator, sequence));
}

}  // namespace swarmnet::flooding
