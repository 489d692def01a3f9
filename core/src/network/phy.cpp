#include "network/phy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "network/nist_error_rate.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/wifi_ofdm.hpp"

namespace swarmnet {

namespace {

// ns-3's PreambleDetectionDuration.
constexpr SimTime kDetectionWindow{4000};
// A lost frame counts as a collision when it would have survived alone with at least this.
constexpr double kCollisionAloneSuccess = 0.9;

}  // namespace

const char* to_string(Phy::State state) {
  switch (state) {
    case Phy::State::idle:
      return "idle";
    case Phy::State::transmitting:
      return "transmitting";
    case Phy::State::receiving:
      return "receiving";
    case Phy::State::busy:
      return "busy";
  }
  return "?";
}

double noise_floor_dbm(const PhyConfig& config) {
  return -174.0 + 10.0 * std::log10(config.bandwidth_hz) + config.noise_figure_db;
}

double audibility_threshold_dbm(const PhyConfig& config) {
  if (config.model == PhyModel::sinr) {
    return noise_floor_dbm(config) + config.interference_floor_db;
  }
  return config.rx_sensitivity_dbm;
}

double event_threshold_dbm(const PhyConfig& config) {
  if (config.model == PhyModel::sinr) {
    return std::max(audibility_threshold_dbm(config),
                    config.cca_threshold_dbm + config.sensing_floor_db);
  }
  return config.rx_sensitivity_dbm;
}

Phy::Phy(const PhyConfig& config, PhyListener& listener, Scheduler* scheduler, std::uint64_t seed)
    : listener_(listener),
      scheduler_(scheduler),
      sinr_(config.model == PhyModel::sinr),
      cca_threshold_dbm_(config.cca_threshold_dbm),
      noise_mw_(dbm_to_milliwatts(noise_floor_dbm(config))),
      energy_detection_mw_(dbm_to_milliwatts(config.energy_detection_dbm)),
      cca_threshold_mw_(dbm_to_milliwatts(config.cca_threshold_dbm)),
      config_(config),
      seed_(seed) {
  if (sinr_model() && scheduler_ == nullptr) {
    throw std::logic_error("PHY: the sinr model needs a scheduler");
  }
}

Phy::State Phy::state() const {
  if (transmitting_) return State::transmitting;
  if (!sinr_model()) return arrivals_.empty() ? State::idle : State::receiving;
  if (lock_) return State::receiving;
  return medium_busy() ? State::busy : State::idle;
}

double Phy::total_mw() const {
  double total = 0.0;
  for (const Arrival& a : arrivals_) total += a.rx_power_mw;
  return total;
}

bool Phy::medium_busy() const {
  if (transmitting_) return true;
  if (!sinr_model()) return !arrivals_.empty();
  if (lock_) return true;
  // ns-3.37 (PhyEntity::SwitchMaybeToCcaBusy): once a preamble is dropped or not detected, CCA is
  // busy while the sum of all arriving signals reaches the CCA threshold; a signal still in its
  // 4 us preamble-detection window is not sensed yet (the "4 us CCA window").
  double sensed_mw = 0.0;
  for (const Arrival& a : arrivals_) {
    if (!a.in_window) sensed_mw += a.rx_power_mw;
  }
  return senses_busy(sensed_mw);
}

bool Phy::senses_busy(double sensed_mw) const {
  return sensed_mw > 0.0 && (sensed_mw >= cca_threshold_mw_ || sensed_mw >= energy_detection_mw_);
}

void Phy::set_quiet_signal_source(const QuietSignalSource* source, NodeId self) {
  quiet_source_ = source;
  self_ = self;
}

double Phy::quiet_mw_now() {
  if (quiet_source_ == nullptr) return 0.0;
  const SimTime now = scheduler_->now();
  quiet_.clear();
  quiet_source_->quiet_signals(self_, now, now + SimTime{1}, quiet_);
  double total = 0.0;
  for (const QuietSignal& signal : quiet_) total += signal.power_mw;
  return total;
}

void Phy::add_quiet_interference(Lock& lock, SimTime end) {
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

void Phy::report_busy_change() {
  const bool busy = medium_busy();
  if (busy == reported_busy_) return;
  reported_busy_ = busy;
  if (busy) {
    listener_.phy_medium_busy();
  } else {
    listener_.phy_medium_idle();
  }
}

void Phy::start_transmission() {
  if (transmitting_) {
    throw std::logic_error("PHY: transmit() while the previous frame is still on the air");
  }
  transmitting_ = true;
  reported_busy_ = true;
  if (sinr_model()) {
    lock_.reset();  // half duplex: the frame being received is lost
    close_window();
  }
}

void Phy::leave_window() {
  for (Arrival& a : arrivals_) a.in_window = false;
}

void Phy::open_window(std::uint64_t sequence) {
  window_open_ = true;
  window_end_ = scheduler_->now() + kDetectionWindow;
  // The opening signal's own key: a timer armed later at (window_end_, sequence) runs where it
  // would have, and the key does not depend on when the PHY learned of the signal.
  window_sequence_ = sequence;
}

void Phy::arm_window_if_needed(bool strong_candidate) {
  if (!window_open_ || detection_timer_ != kNoTimer) return;
  // An open window means no lock and no transmission: its end only judges the candidates and
  // starts sensing them. A candidate strong enough to be detected arms the timer as it arrives,
  // so an unarmed window has none.
  bool matters = strong_candidate;
  if (!matters && !reported_busy_) {
    // Would sensing every arriving signal (as medium_busy() does once the window has ended)
    // make the medium busy? If already busy, more signals keep it so. This test is what lets a
    // passed window close lazily: while it stays unarmed, sensing its signals changes nothing.
    matters = senses_busy(total_mw());
  }
  if (!matters) return;
  detection_timer_ = scheduler_->schedule_reserved(window_end_, window_sequence_, [this] {
    detection_timer_ = kNoTimer;
    end_detection_window();
  });
}

void Phy::close_passed_window() {
  if (window_open_ && detection_timer_ == kNoTimer &&
      scheduler_->has_passed(window_end_, window_sequence_)) {
    close_window();
  }
}

void Phy::close_window() {
  if (detection_timer_ != kNoTimer) scheduler_->cancel(detection_timer_);
  detection_timer_ = kNoTimer;
  window_open_ = false;
  leave_window();
}

void Phy::end_transmission() {
  transmitting_ = false;
  reported_busy_ = medium_busy();
  listener_.phy_transmit_end();
}

void Phy::signal_start(std::uint64_t frame_uid, double rx_power_dbm) {
  signal_start(frame_uid, rx_power_dbm, dbm_to_milliwatts(rx_power_dbm));
}

void Phy::signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw) {
  const std::uint64_t sequence = sinr_model() ? scheduler_->reserve_sequences(1) : 0;
  signal_start(frame_uid, rx_power_dbm, rx_power_mw, sequence);
}

void Phy::signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw,
                       std::uint64_t start_sequence) {
  if (!sinr_model()) {
    arrivals_.push_back(Arrival{frame_uid, rx_power_dbm});
    report_busy_change();
    return;
  }
  close_passed_window();
  const SimTime now = scheduler_->now();
  arrivals_.push_back(Arrival{frame_uid, rx_power_dbm, rx_power_mw, now});
  if (lock_) {
    note_interference_change();
  } else if (!transmitting_) {
    arrivals_.back().in_window = true;
    if (!window_open_) open_window(start_sequence);
    arm_window_if_needed(rx_power_dbm >= cca_threshold_dbm_);
  }
  // No carrier-sense change is possible here: locked or transmitting, the medium is busy anyway,
  // and otherwise the new signal is in the detection window, not sensed yet. (A passed window
  // closed above starts sensing its signals, but it was left unarmed only because that changes
  // nothing: arm_window_if_needed runs at every change of arrivals_ while a window is open.)
}

void Phy::end_detection_window() {
  // Armed timers only: a transmission cancels the window, and a lock begins only here.
  window_open_ = false;
  detect_preamble();
  leave_window();
  // Detected (locked) or not, the window's signals are sensed from now on.
  report_busy_change();
}

void Phy::detect_preamble() {
  const Arrival* best = nullptr;
  for (const Arrival& a : arrivals_) {
    if (a.in_window && (best == nullptr || a.rx_power_mw > best->rx_power_mw)) best = &a;
  }
  if (best == nullptr || best->rx_power_dbm < cca_threshold_dbm_) return;
  const double interference = total_mw() - best->rx_power_mw;
  // Quiet signals count here, but are not kept in the lock's steps: finish_lock adds them then.
  const double sinr_db =
      10.0 * std::log10(best->rx_power_mw / (noise_mw_ + interference + quiet_mw_now()));
  if (sinr_db < config_.preamble_snr_db) return;
  lock_ = Lock{best->frame_uid, best->rx_power_mw, best->start, {}};
  lock_->interference_mw.emplace_back(scheduler_->now(), std::max(interference, 0.0));
}

void Phy::note_interference_change() {
  const double interference = std::max(total_mw() - lock_->power_mw, 0.0);
  lock_->interference_mw.emplace_back(scheduler_->now(), interference);
}

void Phy::signal_end(const Frame& frame, double rx_power_dbm) {
  if (sinr_model()) close_passed_window();
  const auto it = std::find_if(arrivals_.begin(), arrivals_.end(),
                               [&](const Arrival& a) { return a.frame_uid == frame.uid; });
  if (it == arrivals_.end()) return;  // not tracked: nothing to decide
  arrivals_.erase(it);

  if (!sinr_model()) {
    const bool received = rx_power_dbm >= config_.rx_sensitivity_dbm;
    // The medium goes idle before the frame goes up, as a radio's carrier sense drops at the end
    // of the frame and the MAC then processes it.
    report_busy_change();
    if (received) {
      // No noise or interference is modelled: the SINR is unbounded.
      listener_.phy_receive(frame, RxInfo{rx_power_dbm, std::numeric_limits<double>::infinity()});
    } else {
      listener_.phy_receive_error();
    }
    return;
  }

  if (lock_ && lock_->frame_uid == frame.uid) {
    finish_lock(frame, rx_power_dbm);
    return;
  }
  if (lock_) note_interference_change();
  // A signal's end lowers the sensed power: an idle medium stays idle (a float sum of positive
  // terms never grows when one is dropped; a passed window closed above changed nothing, see
  // signal_start).
  if (reported_busy_) report_busy_change();
  arm_window_if_needed(false);
}

double Phy::success_probability(const Lock& lock, const Frame& frame, SimTime end,
                                bool with_interference) const {
  const ofdm::Mode header_mode = ofdm::kModes[0];
  const ofdm::Mode payload_mode = ofdm::mode_at_most(frame.bitrate_bps);
  const SimTime header_start = lock.start + ofdm::kPreambleDuration;
  const SimTime payload_start = header_start + ofdm::kHeaderDuration;
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

void Phy::finish_lock(const Frame& frame, double rx_power_dbm) {
  Lock lock = std::move(*lock_);
  lock_.reset();
  const SimTime now = scheduler_->now();
  add_quiet_interference(lock, now);
  const double p_success = success_probability(lock, frame, now, true);
  RandomStream draw(derive_seed(seed_, {frame.uid}));
  const double draw_value = draw.uniform();
  const bool received = draw_value < p_success;
  // SINR reported to the MAC: over the worst chunk.
  double worst_interference = 0.0;
  for (const auto& chunk : lock.interference_mw) {
    worst_interference = std::max(worst_interference, chunk.second);
  }
  const double sinr_db = 10.0 * std::log10(lock.power_mw / (noise_mw_ + worst_interference));
  report_busy_change();
  if (received) {
    listener_.phy_receive(frame, RxInfo{rx_power_dbm, sinr_db});
    return;
  }
  if (worst_interference > 0.0 &&
      success_probability(lock, frame, now, false) >= kCollisionAloneSuccess) {
    listener_.phy_collision(frame);
  }
  // ns-3.37 reports a reception error (RxEndError, after which the MAC uses EIFS) only when the
  // payload fails; a failed PLCP header aborts the reception during its CCA-busy phase, and the
  // MAC sees a busy medium only. The same draw decides: the header failed if it exceeds the
  // header's own success probability (which bounds the frame's).
  const SimTime header_end = lock.start + ofdm::kPreambleDuration + ofdm::kHeaderDuration;
  if (draw_value >= success_probability(lock, frame, std::min(header_end, now), true)) return;
  listener_.phy_receive_error();
}

}  // namespace swarmnet
