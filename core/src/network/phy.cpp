#include "network/phy.hpp"

#include <stdexcept>

#include "network/sinr_reception.hpp"
#include "network/threshold_reception.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

Phy::Phy(const PhyConfig& config, PhyListener& listener, Scheduler* scheduler, std::uint64_t seed) {
  if (config.model != PhyModel::sinr) {
    model_ = std::make_unique<ThresholdReception>(config, listener);
    return;
  }
  if (scheduler == nullptr) throw std::logic_error("PHY: the sinr model needs a scheduler");
  auto sinr = std::make_unique<SinrReception>(config, listener, *scheduler, seed);
  sinr_ = sinr.get();
  model_ = std::move(sinr);
}

Phy::~Phy() = default;

void Phy::signal_start(std::uint64_t frame_uid, double rx_power_dbm) {
  signal_start(frame_uid, rx_power_dbm, dbm_to_milliwatts(rx_power_dbm));
}

SinrReception& Phy::sinr() const {
  if (sinr_ == nullptr) throw std::logic_error("PHY: far and quiet signals need the sinr model");
  return *sinr_;
}

void Phy::set_quiet_signal_source(const QuietSignalSource* source, NodeId self) {
  sinr().set_quiet_signal_source(source, self);
}

void Phy::set_far_signal_source(FarSignalSource* source, NodeId self) {
  sinr().set_far_signal_source(source, self);
}

void Phy::begin_far_events(const std::vector<FarSignal>& signals) {
  sinr().begin_far_events(signals);
}

EventKey Phy::far_history_start() const { return sinr().far_history_start(); }

void Phy::far_signal_event(const FarSignal& signal) { sinr().far_signal_event(signal); }

void Phy::end_far_events() { sinr().end_far_events(); }

}  // namespace swarmnet
