#include "neighbors.hpp"

#include <algorithm>

namespace swarmnet::aodv {

bool Neighbors::update(NodeId neighbor, SimTime lifetime, SimTime now, bool address_known) {
  const auto [it, added] = entries_.try_emplace(neighbor);
  Entry& entry = it->second;
  entry.expires = std::max(entry.expires, now + lifetime);
  entry.address_known = entry.address_known || address_known;
  entry.closed = false;
  return added;
}

void Neighbors::close(NodeId neighbor) {
  const auto it = entries_.find(neighbor);
  if (it != entries_.end()) it->second.closed = true;
}

bool Neighbors::close_by_address(NodeId neighbor) {
  const auto it = entries_.find(neighbor);
  if (it == entries_.end() || !it->second.address_known) return false;
  it->second.closed = true;
  return true;
}

std::vector<NodeId> Neighbors::purge(SimTime now) {
  std::vector<NodeId> broken;
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->second.closed || it->second.expires < now) {
      broken.push_back(it->first);
      it = entries_.erase(it);
    } else {
      ++it;
    }
  }
  return broken;
}

bool Neighbors::is_neighbor(NodeId node, SimTime now) const {
  const auto it = entries_.find(node);
  return it != entries_.end() && !it->second.closed && it->second.expires >= now;
}

bool Neighbors::address_known(NodeId node) const {
  const auto it = entries_.find(node);
  return it != entries_.end() && it->second.address_known;
}

SimTime Neighbors::expiry(NodeId node) const {
  const auto it = entries_.find(node);
  return it == entries_.end() ? kTimeZero : it->second.expires;
}

}  // namespace swarmnet::aodv
