#include "network/phy.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace swarmnet {

const char* to_string(Phy::State state) {
  switch (state) {
    case Phy::State::idle:
      return "idle";
    case Phy::State::transmitting:
      return "transmitting";
    case Phy::State::receiving:
      return "receiving";
  }
  return "?";
}

Phy::Phy(const PhyConfig& config, PhyListener& listener) : config_(config), listener_(listener) {}

Phy::State Phy::state() const {
  if (transmitting_) return State::transmitting;
  return arrivals_.empty() ? State::idle : State::receiving;
}

double audibility_threshold_dbm(const PhyConfig& config) { return config.rx_sensitivity_dbm; }

bool Phy::audible(double rx_power_dbm) const {
  return rx_power_dbm >= audibility_threshold_dbm(config_);
}

void Phy::start_transmission() {
  if (transmitting_) {
    throw std::logic_error("PHY: transmit() while the previous frame is still on the air");
  }
  transmitting_ = true;
}

void Phy::end_transmission() {
  transmitting_ = false;
  listener_.phy_transmit_end();
}

void Phy::signal_start(std::uint64_t frame_uid, double rx_power_dbm) {
  const bool was_busy = medium_busy();
  arrivals_.push_back(Arrival{frame_uid, rx_power_dbm});
  if (!was_busy) listener_.phy_medium_busy();
}

void Phy::signal_end(const Frame& frame, double rx_power_dbm) {
  const auto it = std::find_if(arrivals_.begin(), arrivals_.end(),
                               [&](const Arrival& a) { return a.frame_uid == frame.uid; });
  if (it == arrivals_.end()) return;  // not tracked: nothing to decide
  const Arrival arrival = *it;
  arrivals_.erase(it);
  const bool received = decide(arrival);
  // The medium goes idle before the frame goes up, as a radio's carrier sense drops at the end of
  // the frame and the MAC then processes it.
  if (!medium_busy()) listener_.phy_medium_idle();
  if (received) {
    // No noise or interference is modelled: the SINR is unbounded.
    listener_.phy_receive(frame, RxInfo{rx_power_dbm, std::numeric_limits<double>::infinity()});
  } else {
    listener_.phy_receive_error();
  }
}

bool Phy::decide(const Arrival& arrival) const {
  return arrival.rx_power_dbm >= config_.rx_sensitivity_dbm;
}

}  // namespace swarmnet
