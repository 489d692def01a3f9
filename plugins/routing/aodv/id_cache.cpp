#include "id_cache.hpp"

namespace swarmnet::aodv {

bool IdCache::is_duplicate(NodeId node, std::uint64_t id, SimTime now) {
  purge(now);
  const Key key{node, id};
  if (expiry_.contains(key)) return true;
  const SimTime expires = now + lifetime_;
  expiry_.emplace(key, expires);
  order_.emplace_back(expires, key);
  return false;
}

bool IdCache::contains(NodeId node, std::uint64_t id, SimTime now) const {
  const auto it = expiry_.find(Key{node, id});
  return it != expiry_.end() && it->second >= now;
}

void IdCache::purge(SimTime now) {
  while (!order_.empty() && order_.front().first < now) {
    expiry_.erase(order_.front().second);
    order_.pop_front();
  }
}

}  // namespace swarmnet::aodv
