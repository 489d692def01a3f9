// `friis` propagation: free-space path loss (ns-3's FriisPropagationLossModel).
#pragma once

#include "swarmnet/propagation.hpp"

namespace swarmnet::friis {

// Free-space loss in dB at `distance_m` (> 0) for wavelength `lambda_m` and system loss.
double friis_loss_db(double distance_m, double lambda_m, double system_loss_db);

class Friis final : public Propagation {
 public:
  static PluginInfo info();
  explicit Friis(const PluginArgs& args);

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const override;
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const override;
  [[nodiscard]] bool varies_per_frame() const override { return false; }

 private:
  [[nodiscard]] double loss_db(double distance_m) const;

  double lambda_m_;
  double system_loss_db_;
  double min_loss_db_;
};

}  // namespace swarmnet::friis
