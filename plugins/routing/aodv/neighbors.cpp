#include "neighbors.hpp"

#include <algorithm>

namespace swarmnet::aodv {

void Neighbors::update(NodeId neighbor, SimTime lifetime, SimTime now) {
  Entry& entry = entries_[neighbor];
  entry.expires = std::max(entry.expires, now + lifetime);
  entry.closed = false;
}

void Neighbors::close(NodeId neighbor) {
  const auto it = entries_.find(neighbor);
  if (it != entries_.end()) it->second.closed = true;
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

SimTime Neighbors::expiry(NodeId node) const {
  const auto it = entries_.find(node);
  return it == entries_.end() ? kTimeZero : it->second.expires;
}

}  // namespace swarmnet::aodv
