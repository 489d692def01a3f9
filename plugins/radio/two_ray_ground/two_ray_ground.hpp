// `two_ray_ground` propagation: ns-2's TwoRayGround model (Friis below the crossover distance,
// the two-ray ground-reflection d^4 law beyond it).
#pragma once

#include "swarmnet/propagation.hpp"

namespace swarmnet::two_ray_ground {

class TwoRayGround final : public Propagation {
 public:
  static PluginInfo info();
  explicit TwoRayGround(const PluginArgs& args);

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const override;
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const override;
  [[nodiscard]] bool varies_per_frame() const override { return false; }

  [[nodiscard]] double loss_db(double distance_m) const;
  [[nodiscard]] double crossover_m() const { return crossover_m_; }

 private:
  double lambda_m_;
  double tx_height_m_;
  double rx_height_m_;
  double system_loss_db_;
  double crossover_m_;
};

}  // namespace swarmnet::two_ray_ground
