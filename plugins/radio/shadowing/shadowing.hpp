// `shadowing` propagation: log-normal shadowing (a zero-mean Gaussian in dB).
#pragma once

#include <cstdint>

#include "swarmnet/propagation.hpp"

namespace swarmnet::shadowing {

// Draws are truncated at +-kBoundSigmas sigma, and +kBoundSigmas sigma is the bound (an untruncated
// Gaussian exceeds it with probability 2.9e-7).
inline constexpr double kBoundSigmas = 5.0;

class Shadowing final : public Propagation {
 public:
  static PluginInfo info();
  explicit Shadowing(const PluginArgs& args);

  [[nodiscard]] double rx_power_dbm(double input_dbm, const RadioLink& link) const override;
  [[nodiscard]] double max_rx_power_dbm(double input_dbm, double distance_m) const override;
  [[nodiscard]] bool varies_per_frame() const override { return per_frame_; }

 private:
  double sigma_db_;
  bool per_frame_;
  bool reciprocal_;  // with !per_frame_: one draw per unordered pair
  std::uint64_t seed_;
};

}  // namespace swarmnet::shadowing
