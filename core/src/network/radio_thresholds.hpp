// The signal levels a PHY configuration implies: the noise floor, and the weakest signals the
// channel must deliver at all, as events, or as far signals (network/phy.hpp).
#pragma once

#include "network/network_settings.hpp"

namespace swarmnet {

// Thermal noise plus noise figure over the configured bandwidth, in dBm.
double noise_floor_dbm(const PhyConfig& config);

// The weakest signal (at the receiver, after its antenna gain) a PHY with `config` takes any
// notice of. The channel's cutoff distance is computed against it, so that skipping nodes beyond
// the cutoff changes nothing. Threshold model: the sensitivity; sinr model: the noise floor plus
// interference_floor_db.
double audibility_threshold_dbm(const PhyConfig& config);

// The lower of the two carrier-sense thresholds (cca_threshold_dbm, energy_detection_dbm), in
// milliwatts: far signals summing to it could make the medium busy.
double sensing_threshold_mw(const PhyConfig& config);

// sinr model: a signal that can be neither detected (below cca_threshold_dbm) nor, alone, make
// the medium busy (below both carrier-sense thresholds). See Phy::begin_far_events. Made once
// per configuration and asked per link: the thresholds' milliwatts are computed once, not per
// link (two pow() calls per link were 1% of a 400-robot run).
class FarSignalTest {
 public:
  explicit FarSignalTest(const PhyConfig& config);
  [[nodiscard]] bool operator()(double rx_power_dbm, double rx_power_mw) const {
    return sinr_ && rx_power_dbm < cca_threshold_dbm_ && rx_power_mw < sensing_mw_;
  }

 private:
  bool sinr_;
  double cca_threshold_dbm_;
  double sensing_mw_;
};

// FarSignalTest(config)(rx_power_dbm, rx_power_mw), for a single question.
bool is_far_signal(const PhyConfig& config, double rx_power_dbm, double rx_power_mw);

// The weakest signal the channel hands to a PHY as an event (signal_start/signal_end): the
// sinr model's sensing threshold, at least the audibility threshold. Signals between the two are
// quiet (see above). Threshold model: the sensitivity.
double event_threshold_dbm(const PhyConfig& config);

}  // namespace swarmnet
