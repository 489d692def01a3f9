// DCF channel access for one station (the logic of ns-3's ChannelAccessManager with one Txop):
// when the medium was last busy, the NAV, EIFS after a failed reception, and the backoff counter,
// which counts whole idle slots after DIFS (or EIFS) and freezes while the medium is busy.
//
// Times: access_start() = max(end of the last busy period, end of the last failed reception +
// EIFS - DIFS, NAV end) + DIFS. Backoff slots elapse from max(access_start(), the point counted
// to so far); a slot interrupted by a busy medium does not count. grant_time() is the earliest
// time the station may transmit if nothing changes.
#pragma once

#include <cstdint>

#include "contention_window.hpp"
#include "dcf_timing.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::dcf80211 {

class ChannelAccess {
 public:
  explicit ChannelAccess(const DcfTiming& timing) : timing_(timing) {}

  // Physical carrier sense (signals or the station's own transmission).
  void medium_busy(SimTime now);
  void medium_idle(SimTime now);
  // A received frame ended: decoded (DIFS applies) or not (EIFS applies from `now`).
  void reception_ended(SimTime now, bool ok);
  // Virtual carrier sense: the NAV is busy until `until` (never shortened).
  void set_nav(SimTime now, SimTime until);
  // Counts `now` as the end of a busy period (a response timeout, like ns-3).
  void busy_until(SimTime now);
  // A new backoff of `slots` slots, counted from now.
  void set_backoff(SimTime now, std::uint32_t slots);
  // No backoff, and no access before `start` (ns-3: the backoff start moved to now + DIFS when a
  // packet arrives at an idle medium).
  void defer_until(SimTime start);

  // Slots still to count, as of `now`.
  [[nodiscard]] std::uint32_t backoff_slots(SimTime now) const;
  [[nodiscard]] bool busy() const { return busy_; }
  [[nodiscard]] SimTime nav_end() const { return nav_end_; }
  [[nodiscard]] SimTime access_start() const;
  // Whether the medium has been idle (physically and virtually) for DIFS/EIFS at `now`.
  [[nodiscard]] bool idle_for_ifs(SimTime now) const { return !busy_ && now >= access_start(); }
  // When access would be granted with the current counter; kTimeNever while the medium is busy.
  [[nodiscard]] SimTime grant_time(SimTime now) const;

 private:
  // Consumes the whole slots elapsed up to `now`.
  void update(SimTime now);
  [[nodiscard]] SimTime count_start() const;

  DcfTiming timing_;
  bool busy_ = false;
  SimTime busy_end_{};
  SimTime failed_rx_end_{};
  bool last_rx_failed_ = false;
  SimTime nav_end_{};
  std::uint32_t slots_ = 0;
  SimTime counted_to_{};
};

}  // namespace swarmnet::dcf80211
