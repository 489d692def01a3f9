// `log_distance` propagation: log-distance path loss (ns-3's LogDistancePropagationLossModel).
#pragma once

#include "swarmnet/path_loss.hpp"

namespace swarmnet::log_distance {

class LogDistance final : public PathLoss {
 public:
  static PluginInfo info();
  explicit LogDistance(const PluginArgs& args);

  [[nodiscard]] double loss_db(double distance_m) const override;

 private:
  double exponent_;
  double reference_distance_m_;
  double reference_loss_db_;
};

}  // namespace swarmnet::log_distance
