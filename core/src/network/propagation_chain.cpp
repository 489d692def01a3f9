#include "network/propagation_chain.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "swarmnet/random.hpp"

namespace swarmnet {

PropagationChain::PropagationChain(const NetworkSettings& settings, PluginLoader& loader) {
  models_.reserve(settings.network.propagation.size());
  std::uint64_t index = 0;
  for (const PluginChoice& choice : settings.network.propagation) {
    PluginArgs args;
    args.params = choice.params;
    args.seed = derive_seed(settings.seed, {hash_name("propagation"), index});
    args.shared_seed = args.seed;
    args.instance = 0;
    args.instance_count = 1;
    models_.push_back(loader.create<Propagation>(choice.name, args));
    ++index;
  }
}

PropagationChain::PropagationChain(std::vector<PluginInstance<Propagation>> models)
    : models_(std::move(models)) {}

double PropagationChain::rx_power_dbm(double tx_power_dbm, const RadioLink& link) const {
  double power = tx_power_dbm;
  for (const auto& model : models_) power = model->rx_power_dbm(power, link);
  return power;
}

double PropagationChain::max_rx_power_dbm(double tx_power_dbm, double distance_m) const {
  double power = tx_power_dbm;
  for (const auto& model : models_) power = model->max_rx_power_dbm(power, distance_m);
  return power;
}

bool PropagationChain::varies_per_frame() const {
  return std::any_of(models_.begin(), models_.end(),
                     [](const auto& model) { return model->varies_per_frame(); });
}

double cutoff_distance_m(const PropagationChain& chain, double tx_power_dbm, double threshold_dbm) {
  const auto audible = [&](double d) {
    return chain.max_rx_power_dbm(tx_power_dbm, d) >= threshold_dbm;
  };
  if (!audible(0.0)) return 0.0;
  double lo = 0.0;  // audible
  double hi = 1.0;
  while (audible(hi)) {
    if (hi > kCutoffSearchLimitM) return std::numeric_limits<double>::infinity();
    lo = hi;
    hi *= 2.0;
  }
  // Invariant: audible(lo), !audible(hi).
  while (hi - lo > kCutoffResolutionM) {
    const double mid = 0.5 * (lo + hi);
    if (audible(mid)) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return hi;
}

}  // namespace swarmnet
