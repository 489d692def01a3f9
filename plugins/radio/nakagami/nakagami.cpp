#include "nakagami.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "swarmnet/random.hpp"

namespace swarmnet::nakagami {

double nakagami_gain_bound(double m, double probability) {
  // f(g) = m (ln g + 1 - g) - ln p decreases for g > 1 from -ln p > 0; bisect for its root.
  const double log_p = std::log(probability);
  const auto f = [&](double g) { return m * (std::log(g) + 1.0 - g) - log_p; };
  double lo = 1.0;
  double hi = 2.0;
  while (f(hi) > 0.0) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return hi;
}

PluginInfo Nakagami::info() {
  return PluginInfo{
      "nakagami",
      "1.0.0",
      "Nakagami-m fading with m per distance band (ns-3 defaults)",
      "Multiplies the input power by a random gain g ~ Gamma(m, 1/m) (mean 1), so the received "
      "amplitude is Nakagami-m distributed, as ns-3's NakagamiPropagationLossModel: m = m0 "
      "below distance1_m, m1 from distance1_m to distance2_m, m2 beyond (ns-3 defaults 80 m, "
      "200 m, 1.5, 0.75, 0.75; m = 1 is Rayleigh fading). Chain it after a path-loss model. "
      "Every (transmitter, receiver, frame) draws its own gain from a stream derived from this "
      "instance's seed and those three numbers, so draws do not depend on which receivers are "
      "visited. The Gamma gain is unbounded; the bound given to the channel's cutoff is the gain "
      "that Gamma(m, 1/m) exceeds with probability below 1e-6 (by the Chernoff bound, so the "
      "true probability is smaller; about +13.5 dB for m = 0.75 and +11.0 dB for m = 1.5), taken "
      "over the band at a distance and every farther one so that it never grows with distance. "
      "A draw above the bound is set to the bound (probability < 1e-6), so the cutoff is exact; "
      "without that truncation it would miss at most a fraction 1e-6 of the frames.",
      {
          real_param("distance1_m", 80.0, "m", "end of the first band (m0)", 0.0, 1e9),
          real_param("distance2_m", 200.0, "m", "end of the second band (m1); >= distance1_m", 0.0,
                     1e9),
          real_param("m0", 1.5, "", "shape below distance1_m", 0.05, 1000.0),
          real_param("m1", 0.75, "", "shape from distance1_m to distance2_m", 0.05, 1000.0),
          real_param("m2", 0.75, "", "shape beyond distance2_m", 0.05, 1000.0),
      }};
}

Nakagami::Nakagami(const PluginArgs& args)
    : distance1_m_(args.params.real("distance1_m")),
      distance2_m_(args.params.real("distance2_m")),
      m_{args.params.real("m0"), args.params.real("m1"), args.params.real("m2")},
      bound_db_{},
      seed_(args.seed) {
  if (distance2_m_ < distance1_m_) {
    throw std::invalid_argument("nakagami: distance2_m must not be below distance1_m");
  }
  double farther = -1e300;
  for (std::size_t i = 3; i-- > 0;) {
    const double bound = 10.0 * std::log10(nakagami_gain_bound(m_[i], kBoundExceedance));
    farther = std::max(farther, bound);
    bound_db_[i] = farther;
  }
}

std::size_t Nakagami::band(double distance_m) const {
  if (distance_m < distance1_m_) return 0;
  if (distance_m < distance2_m_) return 1;
  return 2;
}

double Nakagami::m_at(double distance_m) const { return m_[band(distance_m)]; }

double Nakagami::rx_power_dbm(double input_dbm, const RadioLink& link) const {
  if (input_dbm <= kNoSignalDbm) return input_dbm;
  const double m = m_at(link.distance_m);
  RandomStream draw(derive_seed(seed_, {link.transmitter, link.receiver, link.frame_uid}));
  const double gain_db = 10.0 * std::log10(std::max(draw.gamma(m, 1.0 / m), 1e-300));
  return input_dbm + std::min(gain_db, bound_db_[band(link.distance_m)]);
}

double Nakagami::max_rx_power_dbm(double input_dbm, double distance_m) const {
  if (input_dbm <= kNoSignalDbm) return input_dbm;
  return input_dbm + bound_db_[band(distance_m)];
}

}  // namespace swarmnet::nakagami

SWARMNET_PLUGIN(swarmnet::nakagami::Nakagami)
