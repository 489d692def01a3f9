#include "disk.hpp"

#include <limits>

#include "swarmnet/random.hpp"

namespace swarmnet::disk {

PluginInfo Disk::info() {
  return PluginInfo{
      "disk",
      "1.0.0",
      "Unit-disk radio: full power inside range_m, nothing beyond, optional per-frame loss",
      "A link carries the input power unchanged (no path loss) when the distance is at most "
      "range_m, and no signal (kNoSignalDbm) beyond it. Inside the range each frame gets through "
      "with probability `probability`, drawn independently per (transmitter, receiver, frame) "
      "from a stream derived from this instance's seed, so draws do not depend on the order in "
      "which receivers are visited. `unlimited: true` (or range_m: .inf) makes every node hear "
      "every other: the idealised 'all' model of the RoboNetSim study. With the default PHY (tx "
      "power above the sensitivity) the channel's cutoff distance equals range_m. Chain it "
      "alone, or first, since it passes the input power through.",
      {
          real_param("range_m", 120.0, "m",
                     "communication range; a node farther than this hears nothing (.inf: no limit)",
                     0.0, std::numeric_limits<double>::infinity()),
          bool_param("unlimited", false,
                     "every node hears every other whatever the distance (overrides range_m)"),
          real_param("probability", 1.0, "",
                     "probability that a frame inside the range gets through, per link and frame",
                     0.0, 1.0),
      }};
}

Disk::Disk(const PluginArgs& args)
    : range_m_(args.params.real("range_m")),
      unlimited_(args.params.boolean("unlimited")),
      probability_(args.params.real("probability")),
      seed_(args.seed) {}

double Disk::rx_power_dbm(double input_dbm, const RadioLink& link) const {
  if (!in_range(link.distance_m)) return kNoSignalDbm;
  if (probability_ >= 1.0) return input_dbm;
  RandomStream draw(derive_seed(seed_, {link.transmitter, link.receiver, link.frame_uid}));
  return draw.bernoulli(probability_) ? input_dbm : kNoSignalDbm;
}

double Disk::max_rx_power_dbm(double input_dbm, double distance_m) const {
  return in_range(distance_m) ? input_dbm : kNoSignalDbm;
}

}  // namespace swarmnet::disk

SWARMNET_PLUGIN(swarmnet::disk::Disk)
