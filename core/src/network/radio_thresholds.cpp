#include "network/radio_thresholds.hpp"

#include <algorithm>
#include <cmath>

#include "swarmnet/units.hpp"

namespace swarmnet {

double noise_floor_dbm(const PhyConfig& config) {
  return -174.0 + 10.0 * std::log10(config.bandwidth_hz) + config.noise_figure_db;
}

double audibility_threshold_dbm(const PhyConfig& config) {
  if (config.model == PhyModel::sinr) {
    return noise_floor_dbm(config) + config.interference_floor_db;
  }
  return config.rx_sensitivity_dbm;
}

double sensing_threshold_mw(const PhyConfig& config) {
  return std::min(dbm_to_milliwatts(config.cca_threshold_dbm),
                  dbm_to_milliwatts(config.energy_detection_dbm));
}

FarSignalTest::FarSignalTest(const PhyConfig& config)
    : sinr_(config.model == PhyModel::sinr),
      cca_threshold_dbm_(config.cca_threshold_dbm),
      sensing_mw_(sensing_threshold_mw(config)) {}

bool is_far_signal(const PhyConfig& config, double rx_power_dbm, double rx_power_mw) {
  return FarSignalTest(config)(rx_power_dbm, rx_power_mw);
}

double event_threshold_dbm(const PhyConfig& config) {
  if (config.model == PhyModel::sinr) {
    return std::max(audibility_threshold_dbm(config),
                    config.cca_threshold_dbm + config.sensing_floor_db);
  }
  return config.rx_sensitivity_dbm;
}

}  // namespace swarmnet
