#include "shadowing.hpp"

#include <algorithm>

#include "swarmnet/random.hpp"

namespace swarmnet::shadowing {

PluginInfo Shadowing::info() {
  return PluginInfo{
      "shadowing",
      "1.0.0",
      "Log-normal shadowing: adds a zero-mean Gaussian X ~ N(0, sigma_db) in dB",
      "Received power = input + X, X ~ N(0, sigma_db^2) in dB, as the random part of ns-2's "
      "Shadowing model (chain it after log_distance for the whole ns-2 model). per_frame: true "
      "draws X per (transmitter, receiver, frame), like ns-2; false draws it once per ordered "
      "link (transmitter, receiver), a static shadowing map. Draws come from streams derived from "
      "this instance's seed and those numbers, so they do not depend on which receivers are "
      "visited. The Gaussian is unbounded; X is truncated at +-5 sigma_db (a draw beyond is set to "
      "the limit, which happens with probability 5.7e-7), and +5 sigma_db is the bound given to "
      "the channel's cutoff. Without the truncation the cutoff would miss at most a fraction "
      "2.9e-7 of the frames; with it the cutoff is exact.",
      {
          real_param("sigma_db", 4.0, "dB", "standard deviation of the shadowing", 0.0, 100.0),
          bool_param("per_frame", true,
                     "draw per frame (true) or once per ordered transmitter-receiver pair"),
          bool_param("reciprocal", false,
                     "with per_frame false: one draw per unordered pair, so a link fades alike "
                     "both ways (shadowing by the terrain between two robots is reciprocal)"),
      }};
}

Shadowing::Shadowing(const PluginArgs& args)
    : sigma_db_(args.params.real("sigma_db")),
      per_frame_(args.params.boolean("per_frame")),
      reciprocal_(args.params.boolean("reciprocal")),
      seed_(args.seed) {}

double Shadowing::rx_power_dbm(double input_dbm, const RadioLink& link) const {
  if (input_dbm <= kNoSignalDbm || sigma_db_ == 0.0) return input_dbm;
  std::uint64_t stream = 0;
  if (per_frame_) {
    stream = derive_seed(seed_, {link.transmitter, link.receiver, link.frame_uid});
  } else if (reciprocal_) {
    stream = derive_seed(seed_, {std::min(link.transmitter, link.receiver),
                                 std::max(link.transmitter, link.receiver)});
  } else {
    stream = derive_seed(seed_, {link.transmitter, link.receiver});
  }
  RandomStream draw(stream);
  const double x = std::clamp(draw.normal(), -kBoundSigmas, kBoundSigmas);
  return input_dbm + sigma_db_ * x;
}

double Shadowing::max_rx_power_dbm(double input_dbm, double /*distance_m*/) const {
  if (input_dbm <= kNoSignalDbm) return input_dbm;
  return input_dbm + kBoundSigmas * sigma_db_;
}

}  // namespace swarmnet::shadowing

SWARMNET_PLUGIN(swarmnet::shadowing::Shadowing)
