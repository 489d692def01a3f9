#include "dcf_timing.hpp"

#include <stdexcept>
#include <string>

namespace swarmnet::dcf80211 {

namespace {

ofdm::Mode checked_mode(double rate_bps, const char* what) {
  const auto mode = ofdm::exact_mode(rate_bps);
  if (!mode) {
    throw std::invalid_argument(std::string("dcf80211: ") + what + " " + std::to_string(rate_bps) +
                                " bit/s is not an 802.11a rate (6, 9, 12, 18, 24, 36, 48 or 54 "
                                "Mbit/s)");
  }
  return *mode;
}

}  // namespace

DcfTiming::DcfTiming(SimTime slot_time, SimTime sifs_time, double data_rate_bps,
                     double control_rate_bps)
    : slot(slot_time),
      sifs(sifs_time),
      difs(sifs_time + 2 * slot_time),
      eifs{},
      ack_timeout(sifs_time + slot_time + ofdm::kPreambleDuration + ofdm::kHeaderDuration),
      cts_timeout(ack_timeout),
      data_mode(checked_mode(data_rate_bps, "data_rate_bps")),
      control_mode(checked_mode(control_rate_bps, "control_rate_bps")) {
  eifs = sifs + ack_duration() + difs;
}

}  // namespace swarmnet::dcf80211
