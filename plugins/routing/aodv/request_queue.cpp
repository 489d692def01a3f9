#include "request_queue.hpp"

#include <algorithm>
#include <utility>

namespace swarmnet::aodv {

RequestQueue::RequestQueue(std::size_t max_len, SimTime max_time, DropCallback drop)
    : max_len_(std::max<std::size_t>(max_len, 1)), max_time_(max_time), drop_(std::move(drop)) {}

bool RequestQueue::enqueue(Packet packet, SimTime now) {
  purge(now);
  const bool duplicate = std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) {
    return e.packet.uid == packet.uid && e.packet.destination == packet.destination;
  });
  if (duplicate) return false;
  if (entries_.size() >= max_len_) {
    const Entry oldest = std::move(entries_.front());
    entries_.pop_front();
    drop_(oldest.packet, DropReason::queue_full);
  }
  entries_.push_back({std::move(packet), now + max_time_});
  return true;
}

std::vector<Packet> RequestQueue::take(NodeId destination, SimTime now) {
  purge(now);
  std::vector<Packet> out;
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->packet.destination == destination) {
      out.push_back(std::move(it->packet));
      it = entries_.erase(it);
    } else {
      ++it;
    }
  }
  return out;
}

void RequestQueue::drop_destination(NodeId destination, DropReason reason, SimTime now) {
  for (const Packet& packet : take(destination, now)) drop_(packet, reason);
}

void RequestQueue::purge(SimTime now) {
  while (!entries_.empty() && entries_.front().expires < now) {
    const Entry expired = std::move(entries_.front());
    entries_.pop_front();
    drop_(expired.packet, DropReason::buffer_timeout);
  }
}

bool RequestQueue::has(NodeId destination) const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [destination](const Entry& e) { return e.packet.destination == destination; });
}

SimTime RequestQueue::next_expiry() const {
  return entries_.empty() ? kTimeNever : entries_.front().expires;
}

}  // namespace swarmnet::aodv
