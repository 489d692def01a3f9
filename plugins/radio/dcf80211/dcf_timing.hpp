// 802.11a DCF timing: interframe spaces, response timeouts and frame durations.
#pragma once

#include <cstdint>

#include "swarmnet/units.hpp"
#include "swarmnet/wifi_ofdm.hpp"

namespace swarmnet::dcf80211 {

// MPDU sizes of the control frames (header and FCS).
inline constexpr std::uint32_t kAckBytes = 14;
inline constexpr std::uint32_t kCtsBytes = 14;
inline constexpr std::uint32_t kRtsBytes = 20;

struct DcfTiming {
  // `data_rate_bps` and `control_rate_bps` must be 802.11a rates (std::invalid_argument).
  DcfTiming(SimTime slot, SimTime sifs, double data_rate_bps, double control_rate_bps);

  SimTime slot;
  SimTime sifs;
  SimTime difs;         // SIFS + 2 slots
  SimTime eifs;         // SIFS + ACK at the control rate + DIFS
  SimTime ack_timeout;  // SIFS + slot + preamble and PLCP header: an ACK must have started by then
  SimTime cts_timeout;  // the same for a CTS
  ofdm::Mode data_mode;
  ofdm::Mode control_mode;

  [[nodiscard]] SimTime data_duration(std::uint32_t mpdu_bytes) const {
    return ofdm::frame_duration(mpdu_bytes, data_mode);
  }
  [[nodiscard]] SimTime ack_duration() const {
    return ofdm::frame_duration(kAckBytes, control_mode);
  }
  [[nodiscard]] SimTime cts_duration() const {
    return ofdm::frame_duration(kCtsBytes, control_mode);
  }
  [[nodiscard]] SimTime rts_duration() const {
    return ofdm::frame_duration(kRtsBytes, control_mode);
  }

  // Duration (NAV) fields: what remains of the exchange after the frame's end.
  [[nodiscard]] SimTime data_nav(bool unicast) const {
    return unicast ? sifs + ack_duration() : kTimeZero;
  }
  [[nodiscard]] SimTime rts_nav(std::uint32_t data_mpdu_bytes) const {
    return 3 * sifs + cts_duration() + data_duration(data_mpdu_bytes) + ack_duration();
  }
  [[nodiscard]] SimTime cts_nav(SimTime rts_nav_value) const {
    const SimTime rest = rts_nav_value - sifs - cts_duration();
    return rest > kTimeZero ? rest : kTimeZero;
  }
};

}  // namespace swarmnet::dcf80211
