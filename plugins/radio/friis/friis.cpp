#include "friis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "swarmnet/units.hpp"

namespace swarmnet::friis {

double friis_loss_db(double distance_m, double lambda_m, double system_loss_db) {
  const double ratio = lambda_m / (4.0 * std::numbers::pi * distance_m);
  return -20.0 * std::log10(ratio) + system_loss_db;
}

PluginInfo Friis::info() {
  return PluginInfo{
      "friis",
      "1.0.0",
      "Free-space (Friis) path loss",
      "Received power = input - L(d), L(d) = 20 log10(4 pi d / lambda) + system_loss_db with "
      "lambda = c / frequency_hz, as ns-3's FriisPropagationLossModel (defaults 5.15 GHz, no "
      "system loss). Like ns-3, the loss is never below min_loss_db, and closer than 3 lambda "
      "(the far field's start) the loss is min_loss_db. Deterministic: the bound for the "
      "channel's cutoff is the model itself.",
      {
          real_param("frequency_hz", 5.15e9, "Hz", "carrier frequency", 1.0, 1.0e12),
          real_param("system_loss_db", 0.0, "dB",
                     "system loss L added to the path loss (ns-3's "
                     "SystemLoss 1 = 0 dB)",
                     0.0, 1000.0),
          real_param("min_loss_db", 0.0, "dB", "smallest loss, and the loss within 3 wavelengths",
                     0.0, 1000.0),
      }};
}

Friis::Friis(const PluginArgs& args)
    : lambda_m_(kSpeedOfLightMps / args.params.real("frequency_hz")),
      system_loss_db_(args.params.real("system_loss_db")),
      min_loss_db_(args.params.real("min_loss_db")) {}

double Friis::loss_db(double distance_m) const {
  if (distance_m <= 3.0 * lambda_m_) return min_loss_db_;
  return std::max(friis_loss_db(distance_m, lambda_m_, system_loss_db_), min_loss_db_);
}

}  // namespace swarmnet::friis

SWARMNET_PLUGIN(swarmnet::friis::Friis)
