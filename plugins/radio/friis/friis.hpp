// `friis` propagation: free-space path loss (ns-3's FriisPropagationLossModel).
#pragma once

#include "swarmnet/path_loss.hpp"

namespace swarmnet::friis {

// Free-space loss in dB at `distance_m` (> 0) for wavelength `lambda_m` and system loss.
double friis_loss_db(double distance_m, double lambda_m, double system_loss_db);

class Friis final : public PathLoss {
 public:
  static PluginInfo info();
  explicit Friis(const PluginArgs& args);

  [[nodiscard]] double loss_db(double distance_m) const override;

 private:
  double lambda_m_;
  double system_loss_db_;
  double min_loss_db_;
};

}  // namespace swarmnet::friis
