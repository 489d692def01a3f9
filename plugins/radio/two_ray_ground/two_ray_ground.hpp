// `two_ray_ground` propagation: ns-2's TwoRayGround model (Friis below the crossover distance,
// the two-ray ground-reflection d^4 law beyond it).
#pragma once

#include "swarmnet/path_loss.hpp"

namespace swarmnet::two_ray_ground {

class TwoRayGround final : public PathLoss {
 public:
  static PluginInfo info();
  explicit TwoRayGround(const PluginArgs& args);

  [[nodiscard]] double loss_db(double distance_m) const override;
  [[nodiscard]] double crossover_m() const { return crossover_m_; }

 private:
  double lambda_m_;
  double tx_height_m_;
  double rx_height_m_;
  double system_loss_db_;
  double crossover_m_;
};

}  // namespace swarmnet::two_ray_ground
