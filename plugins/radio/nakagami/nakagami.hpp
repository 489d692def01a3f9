// `nakagami` propagation: Nakagami-m fast fading with m per distance band (ns-3's
// NakagamiPropagationLossModel).
#pragma once

#include <array>
#include <cstdint>

#include "swarmnet/propagation.hpp"

namespace swarmnet::nakagami {

// Probability that the fading gain exceeds its bound (see nakagami_gain_bound).
inline constexpr double kBoundExceedance = 1e-6;

// A power gain g (linear, mean 1) that Gamma(m, 1/m) exceeds with probability below
// `probability`: the root g > 1 of the Chernoff bound g^m exp(m (1 - g)) = probability.
double nakagami_gain_bound(double m, double probability);

class Nakagami final : public Propagation {
 public:
  static PluginInfo info();
  explicit Nakagami(const PluginArgs& args);

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const override;
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const override;

  [[nodiscard]] double m_at(double distance_m) const;

 private:
  [[nodiscard]] std::size_t band(double distance_m) const;

  double distance1_m_;
  double distance2_m_;
  std::array<double, 3> m_;
  std::array<double, 3> bound_db_;  // bound over this band and every farther one
  std::uint64_t seed_;
};

}  // namespace swarmnet::nakagami
