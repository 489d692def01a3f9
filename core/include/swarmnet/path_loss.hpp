// A deterministic path-loss model: received power is the input less a loss that depends on the
// distance alone (free space, log-distance, two-ray ground). A model derives from PathLoss and
// writes loss_db(); the power, its bound for the channel's cutoff (the model itself) and
// "never varies per frame" follow from that, the same for every such model.
#pragma once

#include "swarmnet/propagation.hpp"

namespace swarmnet {

class PathLoss : public Propagation {
 public:
  // Loss in dB at `distance_m` (>= 0). Must not decrease with distance, as the cutoff needs.
  [[nodiscard]] virtual double loss_db(double distance_m) const = 0;

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const final {
    return input_dbm - loss_db(link.distance_m);
  }
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const final {
    return input_dbm - loss_db(distance_m);
  }
  [[nodiscard]] bool varies_per_frame() const final { return false; }
};

}  // namespace swarmnet
