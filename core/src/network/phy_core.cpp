#include "network/phy_core.hpp"

#include <stdexcept>

namespace swarmnet {

const char* to_string(PhyCore::State state) {
  switch (state) {
    case PhyCore::State::idle:
      return "idle";
    case PhyCore::State::transmitting:
      return "transmitting";
    case PhyCore::State::receiving:
      return "receiving";
    case PhyCore::State::busy:
      return "busy";
  }
  return "?";
}

PhyCore::State PhyCore::state() const {
  if (transmitting_) return State::transmitting;
  if (receiving()) return State::receiving;
  return senses_busy() ? State::busy : State::idle;
}

void PhyCore::report_busy_change() {
  const bool busy = medium_busy();
  if (busy == reported_busy_) return;
  reported_busy_ = busy;
  if (busy) {
    listener_.phy_medium_busy();
  } else {
    listener_.phy_medium_idle();
  }
}

void PhyCore::start_transmission() {
  if (transmitting_) {
    throw std::logic_error("PHY: transmit() while the previous frame is still on the air");
  }
  transmitting_ = true;
  reported_busy_ = true;
  transmission_started();
}

void PhyCore::end_transmission() {
  transmitting_ = false;
  transmission_ended();
  reported_busy_ = medium_busy();
  listener_.phy_transmit_end();
}

}  // namespace swarmnet
