#include "two_ray_ground.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "swarmnet/units.hpp"

namespace swarmnet::two_ray_ground {

PluginInfo TwoRayGround::info() {
  return PluginInfo{
      "two_ray_ground",
      "1.0.0",
      "Two-ray ground reflection with ns-2's crossover distance (Friis below it)",
      "As ns-2's TwoRayGround: with lambda = c / frequency_hz and the crossover distance "
      "d_c = 4 pi h_t h_r / lambda, the loss is Friis' 20 log10(4 pi d / lambda) + L below d_c "
      "and 40 log10(d) - 20 log10(h_t h_r) + L at and beyond it (the two expressions are equal "
      "at d_c, so the loss is continuous). Antenna heights are above the ground plane of the "
      "arena; robots are on the ground, so they are parameters. The loss is never negative (a "
      "receiver closer than lambda / (4 pi) gets the input power). ns-2's defaults are 1.5 m "
      "antennas and 914 MHz; the default frequency here is 802.11a's 5.15 GHz like the other "
      "models (d_c = 485 m at 1.5 m heights; set frequency_hz: 914e6 for ns-2's 86 m). "
      "Deterministic: the bound for the channel's cutoff is the model itself.",
      {
          real_param("frequency_hz", 5.15e9, "Hz", "carrier frequency", 1.0, 1.0e12),
          real_param("tx_height_m", 1.5, "m", "transmit antenna height above the ground", 1e-3,
                     1e4),
          real_param("rx_height_m", 1.5, "m", "receive antenna height above the ground", 1e-3, 1e4),
          real_param("system_loss_db", 0.0, "dB", "system loss L", 0.0, 1000.0),
      }};
}

TwoRayGround::TwoRayGround(const PluginArgs& args)
    : lambda_m_(kSpeedOfLightMps / args.params.real("frequency_hz")),
      tx_height_m_(args.params.real("tx_height_m")),
      rx_height_m_(args.params.real("rx_height_m")),
      system_loss_db_(args.params.real("system_loss_db")),
      crossover_m_(4.0 * std::numbers::pi * tx_height_m_ * rx_height_m_ / lambda_m_) {}

double TwoRayGround::loss_db(double distance_m) const {
  double loss = 0.0;
  if (distance_m < crossover_m_) {
    loss = 20.0 * std::log10(4.0 * std::numbers::pi * distance_m / lambda_m_);
  } else {
    loss = 40.0 * std::log10(distance_m) - 20.0 * std::log10(tx_height_m_ * rx_height_m_);
  }
  return std::max(loss + system_loss_db_, 0.0);
}

}  // namespace swarmnet::two_ray_ground

SWARMNET_PLUGIN(swarmnet::two_ray_ground::TwoRayGround)
