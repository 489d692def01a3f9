#include "duplicate_cache.hpp"

#include <algorithm>

namespace swarmnet::flooding {

DuplicateCache::DuplicateCache(std::size_t capacity) : order_(std::max<std::size_t>(capacity, 1)) {}

bool DuplicateCache::insert(NodeId originator, std::uint32_t sequence) {
  const std::uint64_t k = key(originator, sequence);
  if (keys_.contains(k)) return false;
  if (keys_.size() == order_.size()) keys_.erase(order_[next_]);  // evict the oldest
  keys_.insert(k);
  order_[next_] = k;
  next_ = (next_ + 1) % order_.size();
  return true;
}

bool DuplicateCache::contains(NodeId originator, std::uint32_t sequence) const {
  return keys_.contains(key(originator, sequence));
}

}  // namespace swarmnet::flooding
