// The threshold reception model (network/phy.hpp): a frame is received if and only if its power
// reaches rx_sensitivity_dbm; overlapping frames do not interfere, a node receives while it
// transmits, and the medium is busy while any signal arrives.
#pragma once

#include <cstdint>
#include <vector>

#include "network/network_settings.hpp"
#include "network/phy_core.hpp"

namespace swarmnet {

class ThresholdReception final : public PhyCore {
 public:
  ThresholdReception(const PhyConfig& config, PhyListener& listener)
      : PhyCore(listener), rx_sensitivity_dbm_(config.rx_sensitivity_dbm) {}

  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw,
                    std::uint64_t start_sequence) override;
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw) override;
  void signal_end(const Frame& frame, double rx_power_dbm) override;

 protected:
  [[nodiscard]] bool senses_busy() const override { return !arriving_.empty(); }
  [[nodiscard]] bool receiving() const override { return !arriving_.empty(); }

 private:
  double rx_sensitivity_dbm_;
  std::vector<std::uint64_t> arriving_;  // the frames whose signals are arriving, by uid
};

}  // namespace swarmnet
