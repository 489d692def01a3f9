#include "range.hpp"

#include <limits>

namespace swarmnet::range {

PluginInfo Range::info() {
  return PluginInfo{
      "range",
      "1.0.0",
      "Hard range cutoff: input power up to max_range_m, no signal beyond",
      "Passes the input power unchanged when the distance is at most max_range_m and returns no "
      "signal (kNoSignalDbm) beyond, as ns-3's RangePropagationLossModel (default 250 m). Chain "
      "it after a path-loss model to cut off interference beyond a distance, or alone for a "
      "unit disk. Deterministic: the bound for the channel's cutoff is the model itself.",
      {
          real_param("max_range_m", 250.0, "m", "distance beyond which nothing is received", 0.0,
                     std::numeric_limits<double>::infinity()),
      }};
}

Range::Range(const PluginArgs& args) : max_range_m_(args.params.real("max_range_m")) {}

double Range::rx_power_dbm(double input_dbm, const RadioLink& link) const {
  return link.distance_m <= max_range_m_ ? input_dbm : kNoSignalDbm;
}

double Range::max_rx_power_dbm(double input_dbm, double distance_m) const {
  return distance_m <= max_range_m_ ? input_dbm : kNoSignalDbm;
}

}  // namespace swarmnet::range

SWARMNET_PLUGIN(swarmnet::range::Range)
