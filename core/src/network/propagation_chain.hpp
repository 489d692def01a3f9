// The scenario's propagation models, applied in order (ns-3 style chaining), and the cutoff
// distance derived from their bounds.
#pragma once

#include <cstddef>
#include <vector>

#include "network/network_settings.hpp"
#include "plugin/plugin_instance.hpp"
#include "plugin/plugin_loader.hpp"
#include "swarmnet/propagation.hpp"

namespace swarmnet {

class PropagationChain {
 public:
  // One instance per chain entry (shared by every link), seeded with
  // derive_seed(settings.seed, {hash_name("propagation"), index}).
  PropagationChain(const NetworkSettings& settings, PluginLoader& loader);
  // For tests: a chain of ready-made models.
  explicit PropagationChain(std::vector<PluginInstance<Propagation>> models);

  // Each model's rx_power_dbm applied to the previous one's output, starting at `tx_power_dbm`.
  [[nodiscard]] double rx_power_dbm(double tx_power_dbm, const RadioLink& link) const;
  // Each model's max_rx_power_dbm bound applied in the same way.
  [[nodiscard]] double max_rx_power_dbm(double tx_power_dbm, double distance_m) const;

  // Whether any model's power depends on the frame (Propagation::varies_per_frame).
  [[nodiscard]] bool varies_per_frame() const;

  [[nodiscard]] std::size_t size() const { return models_.size(); }

 private:
  std::vector<PluginInstance<Propagation>> models_;
};

// Distances searched for the cutoff: beyond kCutoffSearchLimitM the chain is taken to never fall
// below the threshold, and the bisection stops when the bracket is kCutoffResolutionM wide.
inline constexpr double kCutoffSearchLimitM = 1.0e7;
inline constexpr double kCutoffResolutionM = 1.0e-3;

// The smallest distance d (to kCutoffResolutionM, rounded up) at which the chain's bound
// max_rx_power_dbm(tx_power_dbm, d) is below `threshold_dbm` (the PHY's audibility threshold,
// e.g. the sensitivity): no receiver at distance >= d can notice a frame. Found by doubling from
// 1 m, then bisection; the bound must not increase with distance. +infinity when it stays at or
// above the threshold up to kCutoffSearchLimitM; 0 when it is below it even at distance 0.
double cutoff_distance_m(const PropagationChain& chain, double tx_power_dbm, double threshold_dbm);

}  // namespace swarmnet
