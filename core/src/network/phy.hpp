// A node's PHY: its transmit/receive state and the decision whether an arriving frame is decoded.
// Two reception models (scenario key network.phy.model):
//
// threshold (the default; the disk/ideal_mac quickstart): a frame is received if and only if its
//   received power is at least rx_sensitivity_dbm. Overlapping frames do not interfere, a node
//   receives while it transmits, signals below the sensitivity are ignored entirely.
//
// sinr: 802.11a OFDM reception as ns-3.37's YansWifiPhy does it with its defaults.
//   - Noise floor N = -174 dBm/Hz + 10 log10(bandwidth_hz) + noise_figure_db (-93.97 dBm at
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
//
// Both models: medium_busy/medium_idle callbacks report the transitions of medium_busy() caused
// by arriving signals; the start and end of the node's own transmission are reported by
// transmit() itself and by transmit_end() instead (a MAC that finishes a transmission asks
// medium_busy()). At the end of a frame the medium-idle callback (if any) comes before the
// receive / receive-error callback.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "network/network_settings.hpp"
#include "network/scheduler.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/mac.hpp"
#include "swarmnet/packet.hpp"

namespace swarmnet {

// A signal too weak to be sensed, as it reaches one receiver.
struct QuietSignal {
  SimTime start;
  SimTime end;
  double power_mw;
};

// A far signal (is_far_signal) as it reaches one receiver: its power, and the keys the channel
// reserved for its first and last bit when the frame was sent.
struct FarSignal {
  std::uint64_t frame_uid;
  double power_dbm;
  double power_mw;
  EventKey start;
  EventKey end;
};

// Where a sinr PHY learns of the far signals it was not handed as events (the channel), and
// tells when it needs them all as events.
class FarSignalSource {
 public:
  // far_starts answers for start keys at most this long before now.
  static constexpr SimTime kFarStartHistory{1'000'000};

  // Appends to `out`, by start key, the far signals reaching `receiver` that it was not handed as
  // events and whose start key lies strictly between `from` and `to`.
  virtual void far_starts(NodeId receiver, EventKey from, EventKey to,
                          std::vector<FarSignal>& out) const = 0;
  // Appends to `out` (in no order) the far signals reaching `receiver` that it was not handed as
  // events and that arrive during (from, to): start before `to`, end after `from`. Answers for
  // `from` no earlier than kFarStartHistory before now, or than the start of the reception
  // under way; signals that ended before the receiver last got far signals as events are not
  // listed (nothing later depends on them).
  virtual void far_signals_during(NodeId receiver, EventKey from, EventKey to,
                                  std::vector<FarSignal>& out) const = 0;

 protected:
  ~FarSignalSource() = default;
};

// Where a sinr PHY finds the quiet signals reaching it (the channel).
class QuietSignalSource {
 public:
  // Appends to `out` the quiet signals that reach `receiver` and overlap [from, to).
  virtual void quiet_signals(NodeId receiver, SimTime from, SimTime to,
                             std::vector<QuietSignal>& out) const = 0;

 protected:
  ~QuietSignalSource() = default;
};

// What the PHY tells the layer above (the node, which forwards to its MAC).
class PhyListener {
 public:
  virtual void phy_transmit_end() = 0;
  virtual void phy_receive(const Frame& frame, const RxInfo& info) = 0;
  virtual void phy_receive_error() = 0;
  virtual void phy_medium_busy() = 0;
  virtual void phy_medium_idle() = 0;
  // sinr model: a locked frame was lost to interference (see above); before phy_receive_error.
  virtual void phy_collision(const Frame& /*frame*/) {}

 protected:
  ~PhyListener() = default;
};

// Thermal noise plus noise figure over the configured bandwidth, in dBm.
double noise_floor_dbm(const PhyConfig& config);

// The weakest signal (at the receiver, after its antenna gain) a PHY with `config` takes any
// notice of. The channel's cutoff distance is computed against it, so that skipping nodes beyond
// the cutoff changes nothing. Threshold model: the sensitivity; sinr model: the noise floor plus
// interference_floor_db.
double audibility_threshold_dbm(const PhyConfig& config);

// sinr model: a signal that can be neither detected (below cca_threshold_dbm) nor, alone, make
// the medium busy (below both carrier-sense thresholds). See Phy::begin_far_events.
bool is_far_signal(const PhyConfig& config, double rx_power_dbm, double rx_power_mw);

// The weakest signal the channel hands to a PHY as an event (signal_start/signal_end): the
// sinr model's sensing threshold, at least the audibility threshold. Signals between the two are
// quiet (see above). Threshold model: the sensitivity.
double event_threshold_dbm(const PhyConfig& config);

class Phy {
 public:
  enum class State : std::uint8_t { idle, transmitting, receiving, busy };

  // `scheduler` is required by the sinr model (preamble detection window); `seed` seeds its
  // reception draws.
  Phy(const PhyConfig& config, PhyListener& listener, Scheduler* scheduler = nullptr,
      std::uint64_t seed = 0);

  // idle; transmitting; receiving (threshold: a frame is arriving; sinr: locked on a frame);
  // busy (sinr: not locked, but carrier sense says busy).
  [[nodiscard]] State state() const;
  [[nodiscard]] bool medium_busy() const;

  // sinr model: where to find the quiet signals reaching this PHY, which is node `self`. Without
  // a source the PHY knows only the signals handed to it.
  void set_quiet_signal_source(const QuietSignalSource* source, NodeId self);
  // sinr model: where to find the far signals this PHY, node `self`, is not handed as events.
  // Without a source every signal comes as events.
  void set_far_signal_source(FarSignalSource* source, NodeId self);

  // The node's own transmission. start_transmission() while transmitting is a MAC bug and throws
  // std::logic_error.
  void start_transmission();
  void end_transmission();

  // A signal's first and last bit reach this node. `rx_power_mw` is rx_power_dbm in milliwatts
  // (the channel computes it once per link and step); the two-argument form converts.
  // `start_sequence` is the scheduler key's sequence number of this start (the channel reserves
  // one per receiver): a detection window this signal opens ends at its start + 4 us with that
  // sequence number, so the window's place among same-instant events does not depend on when the
  // PHY learns of the signal. The forms without it reserve a fresh number (tests).
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw,
                    std::uint64_t start_sequence);
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw);
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm);
  void signal_end(const Frame& frame, double rx_power_dbm);

  // Far signals (sinr model, with a far-signal source). A far signal changes what a node does
  // only (a) while it is locked on a frame (interference), (b) at the end of a preamble-detection
  // window it judges (interference), (c) when it opens or joins a detection window that a
  // stronger signal then joins (the window's end), and (d) in carrier sense, which it can change
  // only when the far signals arriving at once reach a carrier-sense threshold on their own: a
  // sensed signal that is not far keeps the medium busy by itself, and an unsensed one in an
  // open window has armed it. So the channel hands far signals over as events only while the PHY
  // is listening (locked, or with an armed window: a and b) or the far signals still on the air
  // at this node could sum to the threshold (d; the channel keeps that upper bound per node).
  // Between those times they are not handed over at all, and nothing the node does depends on
  // them except (c): when a signal starts at an idle PHY, the PHY first asks the source for the
  // far signals that started since it last looked and replays the windows they opened
  // (sync_window). The result is the same as with every signal as events, to the bit.
  //
  // From now on every far signal comes as events. `signals` (by start key) are those this PHY was
  // not handed that end after far_history_start(): those still to end become events (those
  // already arriving join the arrivals in their place), and a reception under way keeps them all
  // for its interference.
  void begin_far_events(const std::vector<FarSignal>& signals);
  // The reception's start if one is under way, else now.
  [[nodiscard]] EventKey far_history_start() const;
  // One more far signal as events (its start is still to come).
  void far_signal_event(const FarSignal& signal);
  // Far signals are no longer handed over (the ones handed over still run).
  void end_far_events();

 private:
  struct Arrival {
    std::uint64_t frame_uid;
    double rx_power_dbm;
    double rx_power_mw = 0.0;
    SimTime start{};
    std::uint64_t start_sequence = 0;
    bool in_window = false;  // its preamble started in the open window: not carrier-sensed yet
  };
  // A far signal handed over as events: schedules its start (if still to come) and its end.
  void schedule_far_signal(const FarSignal& signal);
  // A signal's end when it is not the locked frame's (all of it for a far signal).
  void end_unlocked_signal(std::uint64_t frame_uid);
  // Replays the detection windows opened by far signals not handed over, up to now.
  void sync_window();
  // The arrivals' total power with the far signals `far` (not handed over) among them, summed in
  // arrival order as one list of arrivals would be.
  [[nodiscard]] double total_mw_with(std::vector<FarSignal>& far) const;
  // With a far-signal source: records an arrival's start or end during a reception (the
  // interference steps are rebuilt at its end, when the far signals are known).
  void note_change(std::uint64_t frame_uid, bool start, double rx_power_mw,
                   std::uint64_t start_sequence);

  void leave_window();  // every arrival's in_window cleared
  // sinr: the frame the PHY is locked on, and the interference it has seen since.
  // An arrival as the steps' rebuild sees it.
  struct Known {
    EventKey start;
    double power_mw;
    std::uint64_t frame_uid;
  };
  // An arrival's start or end during a reception.
  struct Change {
    EventKey key;
    bool start;
    Known arrival;
  };
  struct Lock {
    std::uint64_t frame_uid;
    double power_mw;
    SimTime start;
    std::vector<std::pair<SimTime, double>> interference_mw;  // from each time on
    // With a far-signal source (see rebuild_interference):
    EventKey detected{};
    std::vector<Known> at_detection;  // the arrivals when it was detected
    std::vector<Change> changes;
    // The far signals not handed over that arrived at detection, and those handed over since
    // (with their past).
    std::vector<FarSignal> far;
  };
  // Rebuilds the reception's interference steps from the arrivals when it was detected, the
  // changes since, and the far signals that arrived meanwhile.
  void rebuild_interference(Lock& lock);

  [[nodiscard]] bool sinr_model() const { return sinr_; }
  [[nodiscard]] double total_mw() const;
  // Carrier sense's verdict on this much sensed power (medium_busy() without the lock and the
  // transmission).
  [[nodiscard]] bool senses_busy(double sensed_mw) const;
  void report_busy_change();
  void open_window(SimTime start, std::uint64_t sequence);
  // Arms the open window's timer if its end would detect a frame (`strong_candidate`: one that
  // just joined is strong enough) or change carrier sense.
  void arm_window_if_needed(bool strong_candidate);
  // Closes an open, unarmed window whose end has passed (its end changed nothing).
  void close_passed_window();
  // The same at key `at`: an unarmed window whose end key is before it closes.
  void close_window_before(EventKey at);
  void close_window();
  void end_detection_window();
  // Locks on the strongest signal of the window if it is detected.
  void detect_preamble();
  void note_interference_change();
  void finish_lock(const Frame& frame, double rx_power_dbm);
  // Total power of the quiet signals arriving now.
  [[nodiscard]] double quiet_mw_now();
  // The lock's interference steps with the quiet signals that overlapped it added in.
  void add_quiet_interference(Lock& lock, SimTime end);
  [[nodiscard]] double success_probability(const Lock& lock, const Frame& frame, SimTime end,
                                           bool with_interference) const;

  // Hot state first: the channel touches a PHY per receiver per frame, and for a signal that is
  // not received (most of them) signal_start and signal_end read only these first cache lines;
  // the configuration and the reception-only state come after them.
  PhyListener& listener_;
  Scheduler* scheduler_;
  bool sinr_;  // config_.model == PhyModel::sinr
  bool transmitting_ = false;
  bool reported_busy_ = false;
  // sinr state. The detection window is kept without a timer while its end can change nothing
  // (no candidate strong enough to detect, no carrier-sense change): at a 120 m range most
  // arrivals are far too weak, and a timer per idle receiver per frame was a third of all events.
  // Its key (end, reserved sequence number) is kept, and the timer is armed at that key as soon
  // as the end matters (arm_window_if_needed), so everything runs in the order it would with a
  // timer per window; a window that passed without one is closed at the PHY's next event.
  bool window_open_ = false;
  double cca_threshold_dbm_;
  double noise_mw_;
  double energy_detection_mw_;
  double cca_threshold_mw_;
  std::vector<Arrival> arrivals_;  // signals currently arriving, in arrival order
  SimTime window_end_{};
  std::uint64_t window_sequence_ = 0;
  TimerId detection_timer_ = kNoTimer;  // the armed window's timer
  std::optional<Lock> lock_;
  Lock spare_lock_{};  // the last lock's buffers, reused by the next
  // Colder state.
  PhyConfig config_;
  std::uint64_t seed_;
  const QuietSignalSource* quiet_source_ = nullptr;
  FarSignalSource* far_source_ = nullptr;
  NodeId self_ = kNoNode;
  bool far_events_ = false;  // the source hands every far signal over as events
  // The key up to which the window state includes the far signals not handed over.
  EventKey window_synced_{};
  std::vector<FarSignal> far_scratch_;
  // Scratch for quiet-signal queries and add_quiet_interference (no allocation per reception).
  std::vector<QuietSignal> quiet_;
  std::vector<SimTime> quiet_times_;
  std::vector<std::pair<SimTime, double>> quiet_steps_;
};

const char* to_string(Phy::State state);

}  // namespace swarmnet
