// A PhyListener that records what a PHY tells the layer above, for the PHY tests of both
// reception models.
#pragma once

#include <string>
#include <vector>

#include "network/phy.hpp"

namespace swarmnet::test {

class RecordingPhyListener final : public PhyListener {
 public:
  void phy_transmit_end() override { log.emplace_back("tx_end"); }
  void phy_receive(const Frame& frame, const RxInfo& info) override {
    log.push_back("rx " + std::to_string(frame.uid));
    last_rx = info;
  }
  void phy_receive_error() override { log.emplace_back("rx_error"); }
  void phy_medium_busy() override { log.emplace_back("busy"); }
  void phy_medium_idle() override { log.emplace_back("idle"); }
  void phy_collision(const Frame& frame) override {
    log.push_back("collision " + std::to_string(frame.uid));
  }

  std::vector<std::string> log;
  RxInfo last_rx{};  // of the last frame received
};

}  // namespace swarmnet::test
