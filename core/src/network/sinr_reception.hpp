// The sinr reception model (network/phy.hpp describes it): 802.11a OFDM reception as ns-3.37's
// YansWifiPhy does it with its defaults (preamble detection windows, no capture, chunked SINR
// with the NIST error model, carrier sense on the summed power), with the far signals it is not
// handed as events asked for when they matter (far_signals.hpp) and the opt-in quiet signals.
//
// After a header failure (network.phy.header_failure_cca: ns3). In ns-3.37 the MAC's view of the
// medium is the last CCA-busy period the PHY notified, and a locked frame notifies its preamble's
// rest and then its 4 us L-SIG as such periods. When the L-SIG fails, the PHY aborts and
// notifies the MAC again only if the frame outlasts the CCA-busy end the PHY itself keeps (the
// latest of all it notified). A signal that arrived during the preamble after detection set that
// end to when the summed energy falls below the threshold, which the locked frame keeps busy at
// least to its own end; a signal arriving during the L-SIG notifies the MAC again. So when a
// signal joined during the preamble and none during the L-SIG, ns-3's MAC counts the medium idle
// from the L-SIG's end while the frame is still on the air, and learns otherwise only when the
// next signal arrives and its 4 us detection window ends. `ns3` does what ns-3 does at a failed
// header: the reception is aborted at the header's end (a later preamble can be detected; no
// reception error, so no EIFS), and the MAC is told the medium is idle under those two
// conditions, which approximate the PHY's own CCA-busy end (docs/validation.md, "Flooding: the
// saturated dense row").
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "network/network_settings.hpp"
#include "network/phy_core.hpp"
#include "network/scheduler.hpp"
#include "network/signal_sources.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/wifi_ofdm.hpp"

namespace swarmnet {

class SinrReception final : public PhyCore {
 public:
  // `seed` seeds the reception draws.
  SinrReception(const PhyConfig& config, PhyListener& listener, Scheduler& scheduler,
                std::uint64_t seed);

  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw,
                    std::uint64_t start_sequence) override;
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw) override;
  void signal_end(const Frame& frame, double rx_power_dbm) override;

  // Quiet and far signals: Phy's functions of the same names say what these do.
  void set_quiet_signal_source(const QuietSignalSource* source, NodeId self);
  void set_far_signal_source(FarSignalSource* source, NodeId self);
  void begin_far_events(const std::vector<FarSignal>& signals);
  [[nodiscard]] EventKey far_history_start() const;
  void far_signal_event(const FarSignal& signal);
  void end_far_events();

 protected:
  [[nodiscard]] bool senses_busy() const override;
  [[nodiscard]] bool receiving() const override { return lock_.has_value(); }
  void transmission_started() override;
  void transmission_ended() override;

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
  void leave_window();  // every arrival's in_window cleared
  // An arrival as the steps' rebuild sees it.
  struct Known {
    EventKey start;
    double power_mw = 0.0;
    std::uint64_t frame_uid = 0;
  };
  // An arrival's start or end during a reception.
  struct Change {
    EventKey key;
    bool start = false;
    Known arrival;
  };
  // The frame the PHY is locked on, and the interference it has seen since.
  struct Lock {
    std::uint64_t frame_uid = 0;
    double power_mw = 0.0;
    SimTime start{};
    std::vector<std::pair<SimTime, double>> interference_mw;  // from each time on
    // With a far-signal source (see rebuild_interference):
    EventKey detected{};
    std::vector<Known> at_detection;  // the arrivals when it was detected
    std::vector<Change> changes;
    // The far signals not handed over that arrived at detection, and those handed over since
    // (with their past).
    std::vector<FarSignal> far;

    // Its PLCP header (L-SIG) lies between these, after the preamble.
    [[nodiscard]] SimTime header_start() const { return start + ofdm::kPreambleDuration; }
    [[nodiscard]] SimTime header_end() const { return header_start() + ofdm::kHeaderDuration; }
    // The largest interference of its steps: the worst chunk's.
    [[nodiscard]] double worst_interference_mw() const {
      double worst = 0.0;
      for (const auto& step : interference_mw) worst = std::max(worst, step.second);
      return worst;
    }
  };
  // With a far-signal source: records an arrival's start or end during a reception (the
  // interference steps are rebuilt at its end, when the far signals are known).
  void note_change(bool start, const Known& arrival);
  // Rebuilds the reception's interference steps from the arrivals when it was detected, the
  // changes since, and the far signals that arrived meanwhile.
  void rebuild_interference(Lock& lock);

  [[nodiscard]] double total_mw() const;
  // Carrier sense's verdict on this much sensed power (medium_busy() without the lock and the
  // transmission).
  [[nodiscard]] bool senses_power(double sensed_mw) const;
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
  // header_failure_cca ns3: at the locked frame's header end, decides the header with the draw
  // finish_lock would use; a failed one aborts the reception, and the MAC is told the medium is
  // idle where ns-3's would count it so.
  void judge_header();
  // header_failure_cca ns3: a signal that started at `start` joined the lock during its
  // preamble or its header (or neither: after the header).
  void note_join(const Lock& lock, SimTime start);
  // header_failure_cca ns3 with lazy far signals: notes the joins of the far signals that were
  // not handed over as events, from a copy of the lock whose steps rebuild_interference rebuilt.
  void note_far_joins(const Lock& rebuilt);
  // header_failure_cca ns3: the MAC counts the medium idle (or no longer). While it does, the
  // channel hands this PHY every far signal as events, so that the next one to start is seen.
  void set_mac_told_idle(bool idle);
  // header_failure_cca ns3: a signal arrived while the MAC counts the medium idle; its detection
  // window's end tells the MAC what the PHY senses.
  void resume_sensing_after_window();
  // header_failure_cca ns3: the aborted reception's frame ended; tells the listener if it was a
  // collision, as finish_lock does for a reception that went to the end.
  void report_aborted_collision(const Frame& frame);
  // Total power of the quiet signals arriving now.
  [[nodiscard]] double quiet_mw_now();
  // The lock's interference steps with the quiet signals that overlapped it added in.
  void add_quiet_interference(Lock& lock, SimTime end);
  [[nodiscard]] double success_probability(const Lock& lock, double payload_bitrate_bps,
                                           SimTime end, bool with_interference) const;

  // Hot state first: for a signal that is not received (most of them) signal_start and
  // signal_end read only these first cache lines; the configuration and the reception-only state
  // come after them.
  Scheduler* scheduler_;
  // The detection window is kept without a timer while its end can change nothing
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
  bool ns3_header_rule_;  // network.phy.header_failure_cca: ns3
  // Signals currently arriving, in arrival order: the far ones only when handed over as events.
  std::vector<Arrival> arrivals_;
  SimTime window_end_{};
  std::uint64_t window_sequence_ = 0;
  TimerId detection_timer_ = kNoTimer;  // the armed window's timer
  std::optional<Lock> lock_;
  Lock spare_lock_{};  // the last lock's buffers, reused by the next
  // header_failure_cca ns3 (see the file's comment): a signal joined the lock during its preamble
  // after detection, or during its header; and the MAC was told the medium is idle after a header
  // failure (until the next signal's detection window ends, or the node transmits).
  bool joined_in_preamble_ = false;
  bool joined_in_header_ = false;
  bool mac_told_idle_ = false;
  TimerId header_timer_ = kNoTimer;
  TimerId resume_sensing_timer_ = kNoTimer;
  Lock header_lock_{};  // judge_header's copy of the lock, with far and quiet signals added
  // The receptions judge_header aborted whose frames are still on the air (their collisions are
  // told at their ends; another frame may be locked and aborted meanwhile).
  struct AbortedReception {
    std::uint64_t frame_uid = 0;
    double power_mw = 0.0;
    SimTime start{};
    SimTime first_step{};  // the lock's first interference step (its detection)
    bool interfered = false;
  };
  std::vector<AbortedReception> aborted_;
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

}  // namespace swarmnet
