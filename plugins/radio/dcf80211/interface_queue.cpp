#include "interface_queue.hpp"

#include <utility>

namespace swarmnet::dcf80211 {

bool InterfaceQueue::push(Packet packet, NodeId next_hop, SimTime now) {
  if (full()) return false;
  items_.push_back(Item{std::move(packet), next_hop, now});
  return true;
}

std::optional<InterfaceQueue::Item> InterfaceQueue::pop(
    SimTime now, const std::function<void(const Item&)>& expired) {
  while (!items_.empty()) {
    Item item = std::move(items_.front());
    items_.pop_front();
    if (outlived(item.enqueued_at, now)) {
      expired(item);
      continue;
    }
    place_held_ = true;
    return item;
  }
  return std::nullopt;
}

std::vector<InterfaceQueue::Item> InterfaceQueue::take_expired(SimTime now) {
  std::vector<Item> expired;
  while (!items_.empty() && outlived(items_.front().enqueued_at, now)) {
    expired.push_back(std::move(items_.front()));
    items_.pop_front();
  }
  return expired;
}

}  // namespace swarmnet::dcf80211
