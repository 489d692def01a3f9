#include "network/sinr_reception.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "network/nist_error_rate.hpp"
#include "network/radio_thresholds.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/wifi_ofdm.hpp"

namespace swarmnet {

namespace {

// ns-3's PreambleDetectionDuration.
constexpr SimTime kDetectionWindow{4000};
// How far back sync_window looks for far starts at first (several windows' worth).
constexpr SimTime kSyncLookBack{16000};
// A lost frame counts as a collision when it would have survived alone with at least this.
constexpr double kCollisionAloneSuccess = 0.9;

}  // namespace

SinrReception::SinrReception(const PhyConfig& config, PhyListener& listener, Scheduler& scheduler,
                             std::uint64_t seed)
    : PhyCore(listener),
      scheduler_(&scheduler),
      cca_threshold_dbm_(config.cca_threshold_dbm),
      noise_mw_(dbm_to_milliwatts(noise_floor_dbm(config))),
      energy_detection_mw_(dbm_to_milliwatts(config.energy_detection_dbm)),
      cca_threshold_mw_(dbm_to_milliwatts(config.cca_threshold_dbm)),
      ns3_header_rule_(config.header_failure_cca == HeaderFailureCca::ns3),
      config_(config),
      seed_(seed) {}

bool SinrReception::senses_busy() const {
  if (mac_told_idle_) return false;  // header_failure_cca ns3, until the next signal is sensed
  if (lock_) return true;
  // ns-3.37 (PhyEntity::SwitchMaybeToCcaBusy): once a preamble is dropped or not detected, CCA is
  // busy while the sum of all arriving signals reaches the CCA threshold; a signal still in its
  // 4 us preamble-detection window is not sensed yet (the "4 us CCA window").
  double sensed_mw = 0.0;
  for (const Arrival& a : arrivals_) {
    if (!a.in_window) sensed_mw += a.rx_power_mw;
  }
  return senses_power(sensed_mw);
}

bool SinrReception::senses_power(double sensed_mw) const {
  return sensed_mw > 0.0 && (sensed_mw >= cca_threshold_mw_ || sensed_mw >= energy_detection_mw_);
}

void SinrReception::transmission_started() {
  lock_.reset();  // half duplex: the frame being received is lost
  if (header_timer_ != kNoTimer) scheduler_->cancel(header_timer_);
  header_timer_ = kNoTimer;
  if (resume_sensing_timer_ != kNoTimer) scheduler_->cancel(resume_sensing_timer_);
  resume_sensing_timer_ = kNoTimer;
  set_mac_told_idle(false);
  close_window();
}

void SinrReception::transmission_ended() {
  // Far signals that started during the transmission opened no window.
  window_synced_ = scheduler_->current_key();
}

void SinrReception::signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw) {
  signal_start(frame_uid, rx_power_dbm, rx_power_mw, scheduler_->reserve_sequences(1));
}

void SinrReception::signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw,
                                 std::uint64_t start_sequence) {
  if (!lock_ && !transmitting_) sync_window();
  close_passed_window();
  const SimTime now = scheduler_->now();
  arrivals_.push_back(Arrival{frame_uid, rx_power_dbm, rx_power_mw, now, start_sequence});
  if (ns3_header_rule_) {
    if (lock_) note_join(*lock_, now);
    if (mac_told_idle_ && resume_sensing_timer_ == kNoTimer) {
      resume_sensing_timer_ =
          scheduler_->schedule_in(kDetectionWindow, [this] { resume_sensing_after_window(); });
    }
  }
  if (lock_) {
    if (far_source_ != nullptr) {
      note_change(true, Known{EventKey{now, start_sequence}, rx_power_mw, frame_uid});
    } else {
      note_interference_change();
    }
  } else if (!transmitting_) {
    arrivals_.back().in_window = true;
    if (!window_open_) open_window(now, start_sequence);
    arm_window_if_needed(rx_power_dbm >= cca_threshold_dbm_);
  }
  // No carrier-sense change is possible here: locked or transmitting, the medium is busy anyway,
  // and otherwise the new signal is in the detection window, not sensed yet. (A passed window
  // closed above starts sensing its signals, but it was left unarmed only because that changes
  // nothing: arm_window_if_needed runs at every change of arrivals_ while a window is open.)
}

void SinrReception::signal_end(const Frame& frame, double rx_power_dbm) {
  if (!aborted_.empty()) report_aborted_collision(frame);
  if (!lock_ || lock_->frame_uid != frame.uid) {
    end_unlocked_signal(frame.uid);
    return;
  }
  close_passed_window();
  std::erase_if(arrivals_, [&](const Arrival& a) { return a.frame_uid == frame.uid; });
  finish_lock(frame, rx_power_dbm);
}

double SinrReception::total_mw() const {
  double total = 0.0;
  for (const Arrival& a : arrivals_) total += a.rx_power_mw;
  return total;
}

void SinrReception::set_quiet_signal_source(const QuietSignalSource* source, NodeId self) {
  quiet_source_ = source;
  self_ = self;
}

void SinrReception::set_far_signal_source(FarSignalSource* source, NodeId self) {
  far_source_ = source;
  self_ = self;
}

void SinrReception::sync_window() {
  if (far_source_ == nullptr || far_events_) return;
  const EventKey now = scheduler_->current_key();
  if (!(window_synced_ < now)) return;
  if (transmitting_ || lock_) {  // no window opens now, and every window was closed
    window_synced_ = now;
    return;
  }
  // Only the last few far starts can matter: a window lasts 4 us, so a start more than 4 us after
  // the one before it opens a window whatever came earlier. Look back a little, and further only
  // while no such start is found (far starts less than 4 us apart all the way back).
  SimTime look_back = kSyncLookBack;
  std::size_t first = 0;  // the far start the replay begins at
  while (true) {
    const bool cut = now.time - look_back > window_synced_.time + kDetectionWindow;
    const EventKey from = cut ? EventKey{now.time - look_back, 0} : window_synced_;
    far_scratch_.clear();
    far_source_->far_starts(self_, from, now, far_scratch_);
    if (!cut) break;  // from the state at window_synced_, which is exact
    // Every window opened before `from` has ended by a start at least 4 us after it (or by now).
    std::size_t opener = far_scratch_.size();
    for (std::size_t i = far_scratch_.size(); i-- > 0;) {
      const SimTime before = i > 0 ? far_scratch_[i - 1].start.time : from.time;
      if (far_scratch_[i].start.time > before + kDetectionWindow) {
        opener = i;
        break;
      }
    }
    if (opener < far_scratch_.size() || far_scratch_.empty()) {
      if (window_open_) close_window();
      first = far_scratch_.empty() ? 0 : opener;
      break;
    }
    look_back = look_back * 2;
    if (look_back + kDetectionWindow > FarSignalSource::kFarStartHistory) {
      throw std::logic_error(
          "PHY: far signals start less than 4 us apart for longer than the channel keeps them (" +
          std::to_string(FarSignalSource::kFarStartHistory.count()) + " ns)");
    }
  }
  for (std::size_t i = first; i < far_scratch_.size(); ++i) {
    // signal_start for a far signal at an idle PHY, less what cannot matter (see far_events).
    const FarSignal& signal = far_scratch_[i];
    close_window_before(signal.start);
    if (!window_open_) open_window(signal.start.time, signal.start.sequence);
  }
  window_synced_ = now;
}

void SinrReception::begin_far_events(const std::vector<FarSignal>& signals) {
  sync_window();
  close_passed_window();
  far_events_ = true;
  for (const FarSignal& signal : signals) {
    // A reception under way rebuilds its steps from these too (the source no longer lists them).
    if (lock_) lock_->far.push_back(signal);
    if (!scheduler_->has_passed(signal.end.time, signal.end.sequence)) schedule_far_signal(signal);
  }
}

EventKey SinrReception::far_history_start() const {
  return lock_ ? lock_->detected : scheduler_->current_key();
}

void SinrReception::far_signal_event(const FarSignal& signal) { schedule_far_signal(signal); }

void SinrReception::end_far_events() {
  far_events_ = false;
  window_synced_ = scheduler_->current_key();
}

void SinrReception::schedule_far_signal(const FarSignal& signal) {
  const std::uint64_t uid = signal.frame_uid;
  scheduler_->schedule_reserved(signal.end.time, signal.end.sequence,
                                [this, uid] { end_unlocked_signal(uid); });
  if (!scheduler_->has_passed(signal.start.time, signal.start.sequence)) {
    const double dbm = signal.power_dbm;
    const double mw = signal.power_mw;
    const std::uint64_t sequence = signal.start.sequence;
    scheduler_->schedule_reserved(signal.start.time, sequence, [this, uid, dbm, mw, sequence] {
      signal_start(uid, dbm, mw, sequence);
    });
    return;
  }
  // Already arriving: it joins the arrivals in start order, in the open window if it started in
  // it (every signal that started at an idle PHY since the window opened is in it; see
  // sync_window, run just before).
  const EventKey opener{window_end_ - kDetectionWindow, window_sequence_};
  const auto before = [&](const Arrival& a) {
    return EventKey{a.start, a.start_sequence} < signal.start;
  };
  auto position = arrivals_.end();
  while (position != arrivals_.begin() && !before(*std::prev(position))) --position;
  arrivals_.insert(position,
                   Arrival{uid, signal.power_dbm, signal.power_mw, signal.start.time,
                           signal.start.sequence, window_open_ && !(signal.start < opener)});
}

double SinrReception::quiet_mw_now() {
  if (quiet_source_ == nullptr) return 0.0;
  const SimTime now = scheduler_->now();
  quiet_.clear();
  quiet_source_->quiet_signals(self_, now, now + SimTime{1}, quiet_);
  double total = 0.0;
  for (const QuietSignal& signal : quiet_) total += signal.power_mw;
  return total;
}

void SinrReception::add_quiet_interference(Lock& lock, SimTime end) {
  if (quiet_source_ == nullptr || lock.interference_mw.empty()) return;
  const SimTime from = lock.interference_mw.front().first;
  quiet_.clear();
  quiet_source_->quiet_signals(self_, from, end, quiet_);
  if (quiet_.empty()) return;
  // The steps change wherever a signal (handed over or quiet) starts or ends.
  std::vector<SimTime>& times = quiet_times_;
  times.clear();
  for (const auto& step : lock.interference_mw) times.push_back(step.first);
  for (const QuietSignal& signal : quiet_) {
    if (signal.start > from && signal.start < end) times.push_back(signal.start);
    if (signal.end > from && signal.end < end) times.push_back(signal.end);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::vector<std::pair<SimTime, double>>& steps = quiet_steps_;
  steps.clear();
  std::size_t event_step = 0;
  for (const SimTime time : times) {
    // The last handed-over step at or before `time` (several may share one instant: the last
    // one holds, as in success_probability).
    while (event_step + 1 < lock.interference_mw.size() &&
           lock.interference_mw[event_step + 1].first <= time) {
      ++event_step;
    }
    double interference = lock.interference_mw[event_step].second;
    for (const QuietSignal& signal : quiet_) {
      if (signal.start <= time && time < signal.end) interference += signal.power_mw;
    }
    steps.emplace_back(time, interference);
  }
  // Swapped, not moved: both buffers keep their capacity for the next reception.
  lock.interference_mw.swap(steps);
}

void SinrReception::leave_window() {
  for (Arrival& a : arrivals_) a.in_window = false;
}

void SinrReception::open_window(SimTime start, std::uint64_t sequence) {
  window_open_ = true;
  window_end_ = start + kDetectionWindow;
  // The opening signal's own key: a timer armed later at (window_end_, sequence) runs where it
  // would have, and the key does not depend on when the PHY learned of the signal.
  window_sequence_ = sequence;
}

void SinrReception::arm_window_if_needed(bool strong_candidate) {
  if (!window_open_ || detection_timer_ != kNoTimer) return;
  // An open window means no lock and no transmission: its end only judges the candidates and
  // starts sensing them. A candidate strong enough to be detected arms the timer as it arrives,
  // so an unarmed window has none.
  bool matters = strong_candidate;
  if (!matters && !reported_busy_) {
    // Would sensing every arriving signal (as medium_busy() does once the window has ended)
    // make the medium busy? If already busy, more signals keep it so. This test is what lets a
    // passed window close lazily: while it stays unarmed, sensing its signals changes nothing.
    matters = senses_power(total_mw());
  }
  if (!matters) return;
  detection_timer_ = scheduler_->schedule_reserved(window_end_, window_sequence_, [this] {
    detection_timer_ = kNoTimer;
    end_detection_window();
  });
}

void SinrReception::close_passed_window() {
  if (window_open_ && detection_timer_ == kNoTimer &&
      scheduler_->has_passed(window_end_, window_sequence_)) {
    close_window();
  }
}

void SinrReception::close_window_before(EventKey at) {
  if (window_open_ && detection_timer_ == kNoTimer &&
      EventKey{window_end_, window_sequence_} < at) {
    close_window();
  }
}

void SinrReception::close_window() {
  if (detection_timer_ != kNoTimer) scheduler_->cancel(detection_timer_);
  detection_timer_ = kNoTimer;
  window_open_ = false;
  leave_window();
}

void SinrReception::end_detection_window() {
  // Armed timers only: a transmission cancels the window, and a lock begins only here.
  window_open_ = false;
  // The far signals not handed over that started in the window joined it, and it is over.
  window_synced_ = scheduler_->current_key();
  detect_preamble();
  leave_window();
  // Detected (locked) or not, the window's signals are sensed from now on.
  report_busy_change();
}

void SinrReception::detect_preamble() {
  const Arrival* best = nullptr;
  for (const Arrival& a : arrivals_) {
    if (a.in_window && (best == nullptr || a.rx_power_mw > best->rx_power_mw)) best = &a;
  }
  if (best == nullptr || best->rx_power_dbm < cca_threshold_dbm_) return;
  double total = 0.0;
  if (far_source_ != nullptr) {
    // The far signals arriving now that were not handed over count as well.
    const EventKey now = scheduler_->current_key();
    far_scratch_.clear();
    far_source_->far_signals_during(self_, now, now, far_scratch_);
    total = total_mw_with(far_scratch_);
  } else {
    total = total_mw();
  }
  const double interference = total - best->rx_power_mw;
  // Quiet signals count here, but are not kept in the lock's steps: finish_lock adds them then.
  const double sinr_db =
      10.0 * std::log10(best->rx_power_mw / (noise_mw_ + interference + quiet_mw_now()));
  if (sinr_db < config_.preamble_snr_db) return;
  lock_ = std::move(spare_lock_);  // its buffers, emptied
  lock_->frame_uid = best->frame_uid;
  lock_->power_mw = best->rx_power_mw;
  lock_->start = best->start;
  lock_->interference_mw.clear();
  lock_->at_detection.clear();
  lock_->changes.clear();
  lock_->far.clear();
  lock_->interference_mw.emplace_back(scheduler_->now(), std::max(interference, 0.0));
  if (ns3_header_rule_) {
    joined_in_preamble_ = false;
    joined_in_header_ = false;
    header_timer_ = scheduler_->schedule_in(lock_->header_end() - scheduler_->now(),
                                            [this] { judge_header(); });
  }
  if (far_source_ != nullptr) {
    lock_->detected = scheduler_->current_key();
    lock_->far = far_scratch_;  // the far signals arriving at detection
    for (const Arrival& a : arrivals_) {
      lock_->at_detection.push_back(
          Known{EventKey{a.start, a.start_sequence}, a.rx_power_mw, a.frame_uid});
    }
  }
}

double SinrReception::total_mw_with(std::vector<FarSignal>& far) const {
  std::sort(far.begin(), far.end(),
            [](const FarSignal& a, const FarSignal& b) { return a.start < b.start; });
  double total = 0.0;
  auto next_far = far.begin();
  for (const Arrival& a : arrivals_) {
    const EventKey start{a.start, a.start_sequence};
    for (; next_far != far.end() && next_far->start < start; ++next_far) {
      total += next_far->power_mw;
    }
    total += a.rx_power_mw;
  }
  for (; next_far != far.end(); ++next_far) total += next_far->power_mw;
  return total;
}

void SinrReception::note_change(bool start, const Known& arrival) {
  lock_->changes.push_back(Change{scheduler_->current_key(), start, arrival});
}

void SinrReception::rebuild_interference(Lock& lock) {
  const EventKey now = scheduler_->current_key();
  std::vector<FarSignal>& far = far_scratch_;
  far.clear();
  // Those arriving at detection and those handed over since are in lock.far; the others started
  // since.
  far_source_->far_starts(self_, lock.detected, now, far);
  far.insert(far.end(), lock.far.begin(), lock.far.end());
  // A far signal may be listed twice (arriving at detection, then handed over).
  std::sort(far.begin(), far.end(),
            [](const FarSignal& a, const FarSignal& b) { return a.frame_uid < b.frame_uid; });
  far.erase(std::unique(
                far.begin(), far.end(),
                [](const FarSignal& a, const FarSignal& b) { return a.frame_uid == b.frame_uid; }),
            far.end());
  // The arrivals at detection, then every start and end until now, in key order.
  std::vector<Known>& active = lock.at_detection;
  std::vector<Change>& changes = lock.changes;
  for (const FarSignal& f : far) {
    const Known arrival{f.start, f.power_mw, f.frame_uid};
    if (f.start < lock.detected) {
      if (lock.detected < f.end) active.push_back(arrival);
    } else if (f.start < now) {
      changes.push_back(Change{f.start, true, arrival});
    }
    if (lock.detected < f.end && f.end < now) changes.push_back(Change{f.end, false, arrival});
  }
  const auto by_start = [](const Known& a, const Known& b) { return a.start < b.start; };
  std::sort(active.begin(), active.end(), by_start);
  // Changes at one key are one start or end recorded twice (as it ran, and from the source) with
  // equal fields: their order among themselves does not matter, and std::sort allocates nothing.
  std::sort(changes.begin(), changes.end(),
            [](const Change& a, const Change& b) { return a.key < b.key; });
  const auto interference = [&] {
    double total = 0.0;  // in arrival order, as one list of arrivals would sum
    for (const Known& a : active) total += a.power_mw;
    return std::max(total - lock.power_mw, 0.0);
  };
  lock.interference_mw.clear();
  lock.interference_mw.emplace_back(lock.detected.time, interference());
  for (std::size_t i = 0; i < changes.size();) {
    const EventKey key = changes[i].key;
    // The same end may be recorded twice (as it ran, and from the source): one step per key.
    for (; i < changes.size() && changes[i].key == key; ++i) {
      const Change& change = changes[i];
      const auto it = std::find_if(active.begin(), active.end(), [&](const Known& a) {
        return a.frame_uid == change.arrival.frame_uid;
      });
      if (change.start) {
        if (it == active.end()) {
          active.insert(std::upper_bound(active.begin(), active.end(), change.arrival, by_start),
                        change.arrival);
        }
      } else if (it != active.end()) {
        active.erase(it);
      }
    }
    lock.interference_mw.emplace_back(key.time, interference());
  }
}

void SinrReception::note_interference_change() {
  const double interference = std::max(total_mw() - lock_->power_mw, 0.0);
  lock_->interference_mw.emplace_back(scheduler_->now(), interference);
}

void SinrReception::end_unlocked_signal(std::uint64_t frame_uid) {
  close_passed_window();
  const auto it = std::find_if(arrivals_.begin(), arrivals_.end(),
                               [&](const Arrival& a) { return a.frame_uid == frame_uid; });
  if (it == arrivals_.end()) return;  // not tracked: nothing to decide
  const Arrival ended = *it;
  arrivals_.erase(it);
  if (lock_) {
    if (far_source_ != nullptr) {
      note_change(false,
                  Known{EventKey{ended.start, ended.start_sequence}, ended.rx_power_mw, frame_uid});
    } else {
      note_interference_change();
    }
  }
  // A signal's end lowers the sensed power: an idle medium stays idle (a float sum of positive
  // terms never grows when one is dropped; a passed window closed above changed nothing, see
  // signal_start).
  if (reported_busy_) report_busy_change();
  arm_window_if_needed(false);
}

double SinrReception::success_probability(const Lock& lock, double payload_bitrate_bps, SimTime end,
                                          bool with_interference) const {
  const ofdm::Mode header_mode = ofdm::kModes[0];
  const ofdm::Mode payload_mode = ofdm::mode_at_most(payload_bitrate_bps);
  const SimTime header_start = lock.header_start();
  const SimTime payload_start = lock.header_end();
  const auto overlap_s = [](SimTime a0, SimTime a1, SimTime b0, SimTime b1) {
    const SimTime lo = std::max(a0, b0);
    const SimTime hi = std::min(a1, b1);
    return hi > lo ? to_seconds(hi - lo) : 0.0;
  };
  double success = 1.0;
  const auto& chunks = lock.interference_mw;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const SimTime from = chunks[i].first;
    const SimTime to = i + 1 < chunks.size() ? chunks[i + 1].first : end;
    if (to <= from) continue;
    const double interference = with_interference ? chunks[i].second : 0.0;
    const double sinr = lock.power_mw / (noise_mw_ + interference);
    const double header_s = overlap_s(from, to, header_start, payload_start);
    const double payload_s = overlap_s(from, to, payload_start, end);
    success *= chunk_success_rate(header_mode, sinr, header_s * header_mode.rate_bps);
    success *= chunk_success_rate(payload_mode, sinr, payload_s * payload_mode.rate_bps);
  }
  return success;
}

void SinrReception::judge_header() {
  header_timer_ = kNoTimer;
  Lock& lock = *lock_;
  const SimTime header_end = lock.header_end();
  // The header's chunks as finish_lock will score them (its steps up to the header's end are
  // final now); the payload's mode does not matter up to the header's end.
  const Lock* scored = &lock;
  if (quiet_source_ != nullptr || far_source_ != nullptr) {
    header_lock_ = lock;
    // finish_lock rebuilds the lock's own steps at its end; a copy here keeps them for that.
    if (far_source_ != nullptr) {
      rebuild_interference(header_lock_);
      note_far_joins(header_lock_);
    }
    add_quiet_interference(header_lock_, header_end);
    scored = &header_lock_;
  }
  const double p_header = success_probability(*scored, ofdm::kModes[0].rate_bps, header_end, true);
  // finish_lock's draw: the header fails here exactly when it finds it failed there.
  RandomStream draw(derive_seed(seed_, {lock.frame_uid}));
  if (draw.uniform() < p_header) return;
  // ns-3 aborts the reception: a later preamble can be detected, and the frame is one more signal
  // on the air. Whether it was a collision is told at its end, as finish_lock would.
  // Quiet signals count in the worst interference, as in finish_lock.
  aborted_.push_back(AbortedReception{lock.frame_uid, lock.power_mw, lock.start,
                                      lock.interference_mw.front().first,
                                      scored->worst_interference_mw() > 0.0});
  spare_lock_ = std::move(lock);
  lock_.reset();
  // Far signals that started during the reception opened no window. Before the hold below, whose
  // hand-over replays the windows far starts opened since window_synced_.
  window_synced_ = scheduler_->current_key();
  // ns-3's MAC is told the medium's state again unless a signal joined during the preamble and
  // none during the header (the file's comment).
  set_mac_told_idle(joined_in_preamble_ && !joined_in_header_);
  report_busy_change();
}

void SinrReception::note_join(const Lock& lock, SimTime start) {
  if (start < lock.header_start()) {
    joined_in_preamble_ = true;
  } else if (start < lock.header_end()) {
    joined_in_header_ = true;
  }
}

void SinrReception::note_far_joins(const Lock& rebuilt) {
  // The rebuilt steps' starts are every signal that started after detection, far ones included
  // (the others already ran signal_start, which noted them the same way).
  for (const Change& change : rebuilt.changes) {
    if (change.start) note_join(rebuilt, change.key.time);
  }
}

void SinrReception::set_mac_told_idle(bool idle) {
  if (mac_told_idle_ == idle) return;
  mac_told_idle_ = idle;
  if (far_source_ != nullptr) far_source_->hold_far_events(self_, idle);
}

void SinrReception::report_aborted_collision(const Frame& frame) {
  const auto it = std::find_if(aborted_.begin(), aborted_.end(),
                               [&](const AbortedReception& a) { return a.frame_uid == frame.uid; });
  if (it == aborted_.end()) return;
  // finish_lock's test: a frame lost to interference that alone it would have survived.
  Lock& alone = header_lock_;
  alone.power_mw = it->power_mw;
  alone.start = it->start;
  alone.interference_mw.assign(1, {it->first_step, 0.0});
  const bool collision =
      it->interfered && success_probability(alone, frame.bitrate_bps, scheduler_->now(), false) >=
                            kCollisionAloneSuccess;
  aborted_.erase(it);
  if (collision) listener_.phy_collision(frame);
}

void SinrReception::resume_sensing_after_window() {
  resume_sensing_timer_ = kNoTimer;
  set_mac_told_idle(false);
  report_busy_change();
}

void SinrReception::finish_lock(const Frame& frame, double rx_power_dbm) {
  if (header_timer_ != kNoTimer) scheduler_->cancel(header_timer_);  // a frame under 20 us
  header_timer_ = kNoTimer;
  Lock& lock = *lock_;
  const SimTime now = scheduler_->now();
  if (far_source_ != nullptr) rebuild_interference(lock);
  add_quiet_interference(lock, now);
  // SINR reported to the MAC: over the worst chunk.
  const double worst_interference = lock.worst_interference_mw();
  const double worst_sinr = lock.power_mw / (noise_mw_ + worst_interference);
  // Every chunk's SINR is at least the worst one's (the same division, rounding is monotonic):
  // from both modes' certain-success SINR on, every chunk's success rate is exactly 1, and so is
  // their product: such a reception need not walk its chunks. (Few are, where far signals add
  // up: docs/performance.md.)
  const ofdm::Mode payload_mode = ofdm::mode_at_most(frame.bitrate_bps);
  const bool certain = worst_sinr >= certain_success_sinr(ofdm::kModes[0]) &&
                       worst_sinr >= certain_success_sinr(payload_mode);
  const double p_success = certain ? 1.0 : success_probability(lock, frame.bitrate_bps, now, true);
  RandomStream draw(derive_seed(seed_, {frame.uid}));
  const double draw_value = draw.uniform();  // below 1: a certain reception is received
  const bool received = draw_value < p_success;
  const double sinr_db = 10.0 * std::log10(worst_sinr);
  const bool collision =
      !received && worst_interference > 0.0 &&
      success_probability(lock, frame.bitrate_bps, now, false) >= kCollisionAloneSuccess;
  // ns-3.37 reports a reception error (RxEndError, after which the MAC uses EIFS) only when the
  // payload fails; a failed PLCP header aborts the reception during its CCA-busy phase, and the
  // MAC sees a busy medium only. The same draw decides: the header failed if it exceeds the
  // header's own success probability (which bounds the frame's).
  const SimTime header_end = lock.header_end();
  const bool header_received =
      !received &&
      draw_value < success_probability(lock, frame.bitrate_bps, std::min(header_end, now), true);
  // Decided: the lock's buffers are kept for the next one, before the listener runs.
  spare_lock_ = std::move(lock);
  lock_.reset();
  // Far signals that started during the reception opened no window.
  window_synced_ = scheduler_->current_key();
  report_busy_change();
  if (received) {
    listener_.phy_receive(frame, RxInfo{rx_power_dbm, sinr_db});
    return;
  }
  if (collision) listener_.phy_collision(frame);
  if (header_received) listener_.phy_receive_error();
}

}  // namespace swarmnet
