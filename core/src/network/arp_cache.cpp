#include "network/arp_cache.hpp"

#include <utility>

namespace swarmnet {

SimTime ArpCache::timeout(State state) const {
  switch (state) {
    case State::alive:
      return timings_.alive_timeout;
    case State::wait_reply:
      return timings_.wait_reply_timeout;
    case State::dead:
      return timings_.dead_timeout;
  }
  return timings_.alive_timeout;
}

// ns-3's Entry::IsExpired: strictly more than the timeout since the entry was last seen.
bool ArpCache::expired(const Entry& entry, SimTime now) const {
  return now - entry.last_seen > timeout(entry.state);
}

void ArpCache::mark_wait_reply(Entry& entry, Packet& packet, SimTime now) {
  entry.state = State::wait_reply;
  entry.retries = 0;
  entry.pending.clear();
  entry.pending.push_back(std::move(packet));
  entry.last_seen = now;
  ++waiting_;
}

ArpCache::Lookup ArpCache::lookup(NodeId neighbor, Packet& packet, SimTime now) {
  auto [it, added] = entries_.try_emplace(neighbor);
  Entry& entry = it->second;
  if (added) {
    mark_wait_reply(entry, packet, now);
    return Lookup::request;
  }
  if (entry.state == State::wait_reply) {
    // A waiting entry is refreshed by every tick of the wait-reply timer (period = its
    // timeout), so it never counts as expired here; ns-3 treats that case as unreachable.
    if (entry.pending.size() >= timings_.pending_queue_size) return Lookup::drop_queue_full;
    entry.pending.push_back(std::move(packet));
    return Lookup::queued;
  }
  if (expired(entry, now)) {  // an expired alive or dead entry asks again
    mark_wait_reply(entry, packet, now);
    return Lookup::request;
  }
  return entry.state == State::alive ? Lookup::send : Lookup::drop_dead;
}

std::optional<std::deque<Packet>> ArpCache::reply_received(NodeId neighbor, SimTime now) {
  const auto it = entries_.find(neighbor);
  if (it == entries_.end() || it->second.state != State::wait_reply) return std::nullopt;
  Entry& entry = it->second;
  entry.state = State::alive;
  entry.retries = 0;
  entry.last_seen = now;
  --waiting_;
  return std::exchange(entry.pending, {});
}

ArpCache::Timeout ArpCache::wait_reply_timeout(SimTime now) {
  timer_running_ = false;
  Timeout out;
  for (auto& [neighbor, entry] : entries_) {
    if (entry.state != State::wait_reply) continue;
    if (entry.retries < timings_.max_retries) {
      out.retry.push_back(neighbor);
      ++entry.retries;
      entry.last_seen = now;
      continue;
    }
    entry.state = State::dead;
    entry.retries = 0;
    entry.last_seen = now;
    --waiting_;
    out.died.push_back(neighbor);
    for (Packet& packet : entry.pending) out.dropped.push_back(std::move(packet));
    entry.pending.clear();
  }
  return out;
}

bool ArpCache::resolved(NodeId neighbor, SimTime now) const {
  const Entry* entry = find(neighbor);
  return entry != nullptr && entry->state == State::alive && !expired(*entry, now);
}

const ArpCache::Entry* ArpCache::find(NodeId neighbor) const {
  const auto it = entries_.find(neighbor);
  return it == entries_.end() ? nullptr : &it->second;
}

}  // namespace swarmnet
