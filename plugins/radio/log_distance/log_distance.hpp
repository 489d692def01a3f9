// `log_distance` propagation: log-distance path loss (ns-3's LogDistancePropagationLossModel).
#pragma once

#include "swarmnet/propagation.hpp"

namespace swarmnet::log_distance {

class LogDistance final : public Propagation {
 public:
  static PluginInfo info();
  explicit LogDistance(const PluginArgs& args);

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const override;
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const override;
  [[nodiscard]] bool varies_per_frame() const override { return false; }

  [[nodiscard]] double loss_db(double distance_m) const;

 private:
  double exponent_;
  double reference_distance_m_;
  double reference_loss_db_;
};

}  // namespace swarmnet::log_distance
