// `range` propagation: a hard cutoff (ns-3's RangePropagationLossModel).
#pragma once

#include "swarmnet/propagation.hpp"

namespace swarmnet::range {

class Range final : public Propagation {
 public:
  static PluginInfo info();
  explicit Range(const PluginArgs& args);

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const override;
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const override;
  [[nodiscard]] bool varies_per_frame() const override { return false; }

 private:
  double max_range_m_;
};

}  // namespace swarmnet::range
