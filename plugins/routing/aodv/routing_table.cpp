#include "routing_table.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

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

void RoutingTable::age_all(SimTime now) {
  if (now == aged_all_at_) return;
  aged_all_at_ = now;
  for (RouteEntry& entry : slots_) {
    if (entry.destination != kNoNode && !age(entry, now)) remove(entry.destination);
  }
}

RouteEntry* RoutingTable::find(NodeId destination, SimTime now) {
  if (aging_ == RouteAging::whole_table) age_all(now);
  RouteEntry* entry = stored(destination);
  if (entry == nullptr) return nullptr;
  if (!age(*entry, now)) {
    remove(destination);
    return nullptr;
  }
  return entry;
}

RouteEntry* RoutingTable::find_valid(NodeId destination, SimTime now) {
  RouteEntry* entry = find(destination, now);
  return entry != nullptr && entry->is_valid() ? entry : nullptr;
}

const RouteEntry* RoutingTable::entry(NodeId destination) const {
  const std::uint32_t slot = slot_of(destination);
  return slot == 0 ? nullptr : &slots_[slot - 1];
}

RouteEntry& RoutingTable::insert(RouteEntry entry) {
  const NodeId destination = entry.destination;
  if (destination >= node_count_) {
    throw std::logic_error(
        "AODV: a route to node id " + std::to_string(destination) +
        (node_count_ < kNoNode ? ", outside the network's " + std::to_string(node_count_) + " nodes"
                               : std::string{}));
  }
  if (RouteEntry* existing = stored(destination)) return *existing = std::move(entry);
  if (destination >= slot_of_.size()) slot_of_.resize(destination + std::size_t{1}, 0);
  std::uint32_t slot = 0;
  if (free_slots_.empty()) {
    slot = static_cast<std::uint32_t>(slots_.size());
    slots_.push_back(std::move(entry));
  } else {
    slot = free_slots_.back();
    free_slots_.pop_back();
    slots_[slot] = std::move(entry);
  }
  slot_of_[destination] = slot + 1;
  return slots_[slot];
}

bool RoutingTable::erase(NodeId destination) {
  if (stored(destination) == nullptr) return false;
  remove(destination);
  return true;
}

void RoutingTable::remove(NodeId destination) {
  const std::uint32_t slot = slot_of_[destination] - 1;
  slots_[slot] = RouteEntry{};  // destination kNoNode: free
  slot_of_[destination] = 0;
  free_slots_.push_back(slot);
}

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
  for (const RouteEntry& entry : slots_) {
    if (entry.destination == kNoNode || entry.next_hop != next_hop ||
        (valid_only && !entry.is_valid())) {
      continue;
    }
    out.push_back({entry.destination, entry.seq});
  }
  std::sort(out.begin(), out.end(),
            [](const UnreachableDestination& a, const UnreachableDestination& b) {
              return a.destination < b.destination;
            });
  return out;
}

void RoutingTable::purge(SimTime now) {
  age_all(now);
  forget_expired_blacklist(now);
}

void RoutingTable::housekeep(SimTime now) {
  if (aging_ == RouteAging::whole_table) {
    forget_expired_blacklist(now);
  } else {
    purge(now);
  }
}

void RoutingTable::forget_expired_blacklist(SimTime now) {
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
