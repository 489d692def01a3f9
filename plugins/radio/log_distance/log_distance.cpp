#include "log_distance.hpp"

#include <cmath>

namespace swarmnet::log_distance {

PluginInfo LogDistance::info() {
  return PluginInfo{
      "log_distance",
      "1.0.0",
      "Log-distance path loss: L(d) = L0 + 10 n log10(d / d0)",
      "Received power = input - L(d) with L(d) = reference_loss_db + 10 exponent log10(d / "
      "reference_distance_m) beyond the reference distance and reference_loss_db within it, as "
      "ns-3's LogDistancePropagationLossModel. The defaults are ns-3's (exponent 3, 1 m, "
      "46.6777 dB = Friis at 1 m and 5.15 GHz), which YansWifiChannelHelper::Default uses. "
      "Deterministic: the bound for the channel's cutoff is the model itself. With the sinr PHY "
      "and ns-3's -82 dBm detection threshold, the range is R where tx_power_dbm - L(R) = -82 "
      "(about 51.5 m at 16.02 dBm; 120 m needs 27.05 dBm).",
      {
          real_param("exponent", 3.0, "", "path loss exponent n", 0.0, 10.0),
          real_param("reference_distance_m", 1.0, "m", "reference distance d0", 1e-6, 1e6),
          real_param("reference_loss_db", 46.6777, "dB", "loss at the reference distance L0",
                     -1000.0, 1000.0),
      }};
}

LogDistance::LogDistance(const PluginArgs& args)
    : exponent_(args.params.real("exponent")),
      reference_distance_m_(args.params.real("reference_distance_m")),
      reference_loss_db_(args.params.real("reference_loss_db")) {}

double LogDistance::loss_db(double distance_m) const {
  if (distance_m <= reference_distance_m_) return reference_loss_db_;
  return reference_loss_db_ + 10.0 * exponent_ * std::log10(distance_m / reference_distance_m_);
}

}  // namespace swarmnet::log_distance

SWARMNET_PLUGIN(swarmnet::log_distance::LogDistance)
