// A node's PHY: its transmit/receive state and the decision whether an arriving frame is decoded.
// A state core (phy_core.hpp: the node's own transmission, what the layer above was told) and one
// of two reception models, each in its own file (scenario key network.phy.model):
//
// threshold (threshold_reception.hpp; the default, the disk/ideal_mac quickstart): a frame is
// received if and only if its
//   received power is at least rx_sensitivity_dbm. Overlapping frames do not interfere, a node
//   receives while it transmits, signals below the sensitivity are ignored entirely.
//
// sinr (sinr_reception.hpp): 802.11a OFDM reception as ns-3.37's YansWifiPhy does it with its
// defaults.
//   - Noise floor N = -174 dBm/Hz + 10 log10(bandwidth_hz) + noise_figure_db (-93.99 dBm at
//     20 MHz, 7 dB). Signals weaker than N + interference_floor_db (default -10 dB) are ignored
//     (DESIGN.md section 7): the channel does not even deliver them, and its cutoff distance is
//     computed against that floor. Every other arriving signal adds to the interference.
//   - Quiet signals (opt-in): a signal below the sensing threshold (cca_threshold_dbm +
//     sensing_floor_db, e.g. -92 dBm with -10 dB) can neither be detected nor, alone, make the
//     medium busy. The channel does not hand such signals to the PHY one by one (at a 120 m range
//     and -10 dB they are about five in six of all arrivals); the PHY asks the channel for those
//     overlapping a reception when it needs the interference (QuietSignalSource). They count in
//     every SINR exactly as other signals do, but not in the carrier-sense sum: that is the
//     approximation, and it shows under saturation, where many distant transmitters add up
//     (docs/performance.md). The default sensing floor (-100 dB) is below the interference
//     floor, so no signal is quiet and the model is exact.
//   - Preamble detection: a signal arriving while the PHY is neither transmitting nor locked on a
//     frame opens a 4 us detection window (ns-3's PreambleDetectionDuration); signals arriving in
//     the window join it. At its end the strongest of them still arriving is detected if its
//     power is at least cca_threshold_dbm (-82 dBm) and its SINR at least preamble_snr_db (4 dB;
//     ns-3's ThresholdPreambleDetectionModel). The PHY then locks on it until its last bit.
//   - Capture: none (ns-3's default, no frame-capture model). A node locked on a frame treats
//     every later frame, however strong, as interference; a frame arriving while the node
//     transmits is lost, and a transmission that starts while locked aborts the reception.
//   - Success: interference is the sum of the other signals' powers; the locked frame's time is
//     cut into chunks wherever that sum changes (ns-3's InterferenceHelper). The 16 us preamble
//     is not scored; the 4 us PLCP header is scored at 6 Mbit/s (BPSK 1/2) and the rest of the
//     frame at the frame's rate (network/nist_error_rate.hpp), bits = rate x chunk duration. The
//     frame is received with probability prod over chunks of chunk_success_rate, drawn from a
//     stream derived from (node seed, frame uid). A rate that is not an 802.11a rate is read as
//     the fastest 802.11a rate below it.
//   - Errors: the listener's receive-error callback (the MAC's EIFS) follows only a frame whose
//     PLCP header was received and whose payload failed, as ns-3.37's RxEndError; a frame lost
//     in its header leaves only a busy medium.
//   - Collisions: a lost locked frame addressed to this node (or broadcast) whose success
//     probability without interference would have been at least 0.9 counts as a collision
//     (listener->phy_collision; the node counts those addressed to it or broadcast as
//     mac.collisions).
//   - Carrier sense: medium_busy() while transmitting, while locked on a frame, or while the
//     total power of the arriving signals reaches cca_threshold_dbm (ns-3.37's CCA sensitivity:
//     the aggregate, not a single frame, as PhyEntity::SwitchMaybeToCcaBusy) or
//     energy_detection_dbm (-62 dBm, CCA-ED). A signal still in its 4 us preamble-detection
//     window does not count yet (ns-3 reports CCA busy only at the window's end).
//   - Far signals (network.channel.far_signals: lazy, the default): a signal too weak to be
//     detected or to make the medium busy on its own (is_far_signal) changes what a node does
//     only (a) at the end of a detection window it judges and (b) while it is locked on a frame
//     (interference), (c) when it opens or joins a detection window that a stronger signal then
//     joins (the window's end), and (d) in carrier sense, which it can change only when the far
//     signals arriving at once reach a carrier-sense threshold on their own (a sensed signal
//     that is not far keeps the medium busy by itself, and one in an open window has armed it).
//     The channel (far_signals.hpp) keeps an upper bound of the far power still to end at each
//     node and hands far signals over as events only while it reaches the threshold (d). The
//     PHY asks for the others when it needs them: at a window's end (a), at a reception's end,
//     whose interference steps it then rebuilds from the arrivals at detection, the changes
//     since and the far signals (b), and when a signal starts at an idle PHY, where it replays
//     the windows the far signals that started since it last looked opened (c). Under
//     header_failure_cca ns3 a far signal also matters (e) by joining a locked frame's preamble
//     or header, which the PHY asks for when the header ends, and (f) by being the next signal
//     to start while the MAC counts the medium idle, for which the node holds far signals as
//     events (FarSignalSource::hold_far_events). The result is the same as with every signal as
//     events (far_signals: events), to the bit.
//
// Both models: medium_busy/medium_idle callbacks report the transitions of medium_busy() caused
// by arriving signals; the start and end of the node's own transmission are reported by
// transmit() itself and by transmit_end() instead (a MAC that finishes a transmission asks
// medium_busy()). At the end of a frame the medium-idle callback (if any) comes before the
// receive / receive-error callback.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "network/network_settings.hpp"
#include "network/phy_core.hpp"
#include "network/radio_thresholds.hpp"
#include "network/scheduler.hpp"
#include "network/signal_sources.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/packet.hpp"

namespace swarmnet {

class SinrReception;

class Phy {
 public:
  using State = PhyCore::State;

  // `scheduler` is required by the sinr model (preamble detection window); `seed` seeds its
  // reception draws.
  Phy(const PhyConfig& config, PhyListener& listener, Scheduler* scheduler = nullptr,
      std::uint64_t seed = 0);
  Phy(const Phy&) = delete;
  Phy& operator=(const Phy&) = delete;
  Phy(Phy&&) = delete;
  Phy& operator=(Phy&&) = delete;
  ~Phy();

  // idle; transmitting; receiving (threshold: a frame is arriving; sinr: locked on a frame);
  // busy (sinr: not locked, but carrier sense says busy).
  [[nodiscard]] State state() const { return model_->state(); }
  [[nodiscard]] bool medium_busy() const { return model_->medium_busy(); }

  // The node's own transmission. start_transmission() while transmitting is a MAC bug and throws
  // std::logic_error.
  void start_transmission() { model_->start_transmission(); }
  void end_transmission() { model_->end_transmission(); }

  // A signal's first and last bit reach this node. `rx_power_mw` is rx_power_dbm in milliwatts
  // (the channel computes it once per link and step); the two-argument form converts.
  // `start_sequence` is the sequence number of this start's scheduler key (the channel reserves
  // one per receiver): a detection window the signal opens ends at its start + 4 us with that
  // sequence number, so the window's place among same-instant events does not depend on when the
  // PHY learns of the signal. The forms without it reserve a fresh one (tests).
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw,
                    std::uint64_t start_sequence) {
    model_->signal_start(frame_uid, rx_power_dbm, rx_power_mw, start_sequence);
  }
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw) {
    model_->signal_start(frame_uid, rx_power_dbm, rx_power_mw);
  }
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm);
  void signal_end(const Frame& frame, double rx_power_dbm) {
    model_->signal_end(frame, rx_power_dbm);
  }

  // sinr model only (std::logic_error otherwise). Where to find the quiet signals reaching this
  // PHY, which is node `self`; without a source the PHY knows only the signals handed to it.
  void set_quiet_signal_source(const QuietSignalSource* source, NodeId self);
  // Where to find the far signals this PHY, node `self`, is not handed as events; without a
  // source every signal comes as events.
  void set_far_signal_source(FarSignalSource* source, NodeId self);
  // From now on every far signal comes as events. `signals` (by start key) are those this PHY was
  // not handed that end after far_history_start(): those still to end become events (those
  // already arriving join the arrivals in their place), and a reception under way keeps them all
  // for its interference.
  void begin_far_events(const std::vector<FarSignal>& signals);
  // The reception's detection if one is under way, else now.
  [[nodiscard]] EventKey far_history_start() const;
  // One more far signal as events (its start is still to come).
  void far_signal_event(const FarSignal& signal);
  // Far signals are no longer handed over (the ones handed over still run).
  void end_far_events();

 private:
  [[nodiscard]] SinrReception& sinr() const;

  std::unique_ptr<PhyCore> model_;
  SinrReception* sinr_ = nullptr;  // model_ when it is the sinr model
};

}  // namespace swarmnet
