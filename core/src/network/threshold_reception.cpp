#include "network/threshold_reception.hpp"

#include <algorithm>
#include <limits>

namespace swarmnet {

void ThresholdReception::signal_start(std::uint64_t frame_uid, double /*rx_power_dbm*/,
                                      double /*rx_power_mw*/, std::uint64_t /*start_sequence*/) {
  arriving_.push_back(frame_uid);
  report_busy_change();
}

void ThresholdReception::signal_start(std::uint64_t frame_uid, double rx_power_dbm,
                                      double rx_power_mw) {
  signal_start(frame_uid, rx_power_dbm, rx_power_mw, 0);
}

void ThresholdReception::signal_end(const Frame& frame, double rx_power_dbm) {
  const auto it = std::find(arriving_.begin(), arriving_.end(), frame.uid);
  if (it == arriving_.end()) return;  // not tracked: nothing to decide
  arriving_.erase(it);
  const bool received = rx_power_dbm >= rx_sensitivity_dbm_;
  // The medium goes idle before the frame goes up, as a radio's carrier sense drops at the end
  // of the frame and the MAC then processes it.
  report_busy_change();
  if (received) {
    // No noise or interference is modelled: the SINR is unbounded.
    listener_.phy_receive(frame, RxInfo{rx_power_dbm, std::numeric_limits<double>::infinity()});
  } else {
    listener_.phy_receive_error();
  }
}

}  // namespace swarmnet
