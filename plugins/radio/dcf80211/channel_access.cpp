#include "channel_access.hpp"

#include <algorithm>

namespace swarmnet::dcf80211 {

SimTime ChannelAccess::access_start() const {
  SimTime start = std::max(busy_end_, nav_end_);
  if (last_rx_failed_) start = std::max(start, failed_rx_end_ + timing_.eifs - timing_.difs);
  return start + timing_.difs;
}

SimTime ChannelAccess::count_start() const { return std::max(access_start(), counted_to_); }

void ChannelAccess::update(SimTime now) {
  if (busy_ || slots_ == 0) return;
  const SimTime start = count_start();
  if (now <= start) return;
  const auto elapsed = static_cast<std::uint64_t>((now - start) / timing_.slot);
  const auto used = static_cast<std::uint32_t>(std::min<std::uint64_t>(elapsed, slots_));
  slots_ -= used;
  counted_to_ = start + timing_.slot * static_cast<std::int64_t>(used);
}

void ChannelAccess::medium_busy(SimTime now) {
  update(now);
  busy_ = true;
}

void ChannelAccess::medium_idle(SimTime now) {
  if (!busy_) return;
  busy_ = false;
  busy_end_ = std::max(busy_end_, now);
}

void ChannelAccess::reception_ended(SimTime now, bool ok) {
  update(now);
  last_rx_failed_ = !ok;
  if (!ok) failed_rx_end_ = now;
}

void ChannelAccess::set_nav(SimTime now, SimTime until) {
  if (until <= nav_end_) return;
  update(now);
  nav_end_ = until;
}

void ChannelAccess::busy_until(SimTime now) {
  update(now);
  busy_end_ = std::max(busy_end_, now);
}

void ChannelAccess::set_backoff(SimTime now, std::uint32_t slots) {
  slots_ = slots;
  counted_to_ = now;
}

void ChannelAccess::defer_until(SimTime start) {
  slots_ = 0;
  counted_to_ = start;
}

std::uint32_t ChannelAccess::backoff_slots(SimTime now) const {
  ChannelAccess copy = *this;
  copy.update(now);
  return copy.slots_;
}

SimTime ChannelAccess::grant_time(SimTime now) const {
  if (busy_) return kTimeNever;
  const SimTime start = count_start();
  const SimTime grant = start + timing_.slot * static_cast<std::int64_t>(slots_);
  return std::max(grant, now);
}

}  // namespace swarmnet::dcf80211
