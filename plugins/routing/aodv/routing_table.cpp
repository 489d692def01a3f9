#include "routing_table.hpp"

#include <algorithm>

namespace swarmnet::aodv {

const char* to_string(RouteState state) {
  switch (state) {
    case RouteState::valid:
      return "valid";
    case RouteState::invalid:
      return "invalid";
    case RouteState::in_search:
      return "in_search";
  }
  return "?";
}

bool RouteEntry::insert_precursor(NodeId node) {
  const auto it = std::lower_bound(precursors.begin(), precursors.end(), node);
  if (it != precursors.end() && *it == node) return false;
  precursors.insert(it, node);
  return true;
}

bool RouteEntry::has_precursor(NodeId node) const {
  return std::binary_search(precursors.begin(), precursors.end(), node);
}

bool RoutingTable::age(RouteEntry& entry, SimTime now) const {
  if (entry.expires >= now) return true;
  switch (entry.state) {
    case RouteState::valid:
      invalidate(entry, now);
      // As for a broken link: a node that let its route expire must not take back the same
      // sequence number from a longer path that may lead through nodes still routing via it.
      if (entry.valid_seq && increment_seq_on_expiry_) ++entry.seq;
      return true;
    case RouteState::invalid:
      return false;
    case RouteState::in_search:
      return true;
  }
  return true;
}

RouteEntry* RoutingTable::find(NodeId destination, SimTime now) {
  const auto it = entries_.find(destination);
  if (it == entries_.end()) return nullptr;
  if (!age(it->second, now)) {
    entries_.erase(it);
    return nullptr;
  }
  return &it->second;
}

RouteEntry* RoutingTable::find_valid(NodeId destination, SimTime now) {
  RouteEntry* entry = find(destination, now);
  return entry != nullptr && entry->is_valid() ? entry : nullptr;
}

RouteEntry& RoutingTable::insert(RouteEntry entry) {
  const NodeId destination = entry.destination;
  return entries_.insert_or_assign(destination, std::move(entry)).first->second;
}

bool RoutingTable::erase(NodeId destination) { return entries_.erase(destination) > 0; }

void RoutingTable::invalidate(RouteEntry& entry, SimTime now) const {
  if (entry.state != RouteState::valid) return;
  entry.state = RouteState::invalid;
  entry.rreq_count = 0;
  entry.expires = now + delete_period_;
}

bool RoutingTable::refresh(NodeId destination, SimTime lifetime, SimTime now) {
  RouteEntry* entry = find_valid(destination, now);
  if (entry == nullptr) return false;
  entry->rreq_count = 0;
  entry->expires = std::max(entry->expires, now + lifetime);
  return true;
}

std::vector<UnreachableDestination> RoutingTable::valid_destinations_via(NodeId next_hop,
                                                                         SimTime now) {
  return list_via(next_hop, now, true);
}

std::vector<UnreachableDestination> RoutingTable::destinations_via(NodeId next_hop, SimTime now) {
  return list_via(next_hop, now, false);
}

std::vector<UnreachableDestination> RoutingTable::list_via(NodeId next_hop, SimTime now,
                                                           bool valid_only) {
  purge(now);
  std::vector<UnreachableDestination> out;
  for (const auto& [destination, entry] : entries_) {
    if (entry.next_hop != next_hop || (valid_only && !entry.is_valid())) continue;
    out.push_back({destination, entry.seq});
  }
  std::sort(out.begin(), out.end(),
            [](const UnreachableDestination& a, const UnreachableDestination& b) {
              return a.destination < b.destination;
            });
  return out;
}

void RoutingTable::purge(SimTime now) {
  for (auto it = entries_.begin(); it != entries_.end();) {
    it = age(it->second, now) ? std::next(it) : entries_.erase(it);
  }
  std::erase_if(blacklist_, [now](const auto& item) { return item.second < now; });
}

bool RoutingTable::is_blacklisted(NodeId neighbor, SimTime now) {
  const auto it = blacklist_.find(neighbor);
  if (it == blacklist_.end()) return false;
  if (it->second < now) {
    blacklist_.erase(it);
    return false;
  }
  return true;
}

}  // namespace swarmnet::aodv
