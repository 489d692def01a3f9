// `disk` propagation: the unit-disk radio of the reference study (RoboNetSim), optionally lossy.
#pragma once

#include <cstdint>

#include "swarmnet/propagation.hpp"

namespace swarmnet::disk {

class Disk final : public Propagation {
 public:
  static PluginInfo info();
  explicit Disk(const PluginArgs& args);

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const override;
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const override;
  // Only a link that connects with probability < 1 draws per frame.
  [[nodiscard]] bool varies_per_frame() const override { return probability_ < 1.0; }

 private:
  [[nodiscard]] bool in_range(double distance_m) const {
    return unlimited_ || distance_m <= range_m_;
  }

  double range_m_;
  bool unlimited_;
  double probability_;
  std::uint64_t seed_;
};

}  // namespace swarmnet::disk
