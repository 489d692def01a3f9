#include "network/far_signals.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace swarmnet {

namespace {

// A receiver's far power is counted in 2^32 units per sensing threshold.
constexpr double kUnitsPerThreshold = 4294967296.0;
// A float sum of n far powers exceeds their exact sum by at most n x 2^-53 of it: this margin
// keeps the bound an upper bound for any n below 10^7.
constexpr double kRoundingMargin = 1e-9;

bool by_start(const FarSignal& a, const FarSignal& b) { return a.start < b.start; }

}  // namespace

FarSignals::FarSignals(Scheduler& scheduler, const std::vector<Phy*>& phys, double sensing_mw)
    : scheduler_(scheduler),
      phys_(phys),
      units_per_mw_(kUnitsPerThreshold / sensing_mw),
      hot_units_(static_cast<std::int64_t>(kUnitsPerThreshold * (1.0 - kRoundingMargin))),
      receivers_(phys.size()) {}

std::int64_t FarSignals::units(double power_mw) const {
  // Rounded up, plus one for the rounding of the product: never below the exact share.
  return static_cast<std::int64_t>(std::ceil(power_mw * units_per_mw_)) + 1;
}

FarSignal FarSignals::signal_of(const AirFrame& frame, std::size_t link) {
  const ChannelLink& l = frame.links->links[link];
  const EventKey start{frame.sent + l.delay, frame.first_sequence + 2 * link};
  return FarSignal{frame.uid, l.power_dbm, l.power_mw, start,
                   EventKey{start.time + frame.duration, start.sequence + 1}};
}

std::uint64_t FarSignals::oldest_number() const {
  return frames_.empty() ? next_number_ : frames_.front().number;
}

void FarSignals::remember_at(Receiver& r, std::uint64_t oldest, FarEntry entry) {
  // Entries are by number, so the forgotten ones are a prefix. They are dropped only when the
  // list is full, before it would grow: a list never holds more than twice the most frames kept
  // at once, and a push usually costs no more than the push.
  if (r.frames.size() == r.frames.capacity()) {
    const auto kept = std::find_if(r.frames.begin(), r.frames.end(),
                                   [&](const FarEntry& e) { return e.number >= oldest; });
    r.frames.erase(r.frames.begin(), kept);
  }
  r.frames.push_back(entry);
}

void FarSignals::frame_sent(std::uint64_t uid, SimTime duration, std::uint64_t first_sequence,
                            std::shared_ptr<const ChannelLinks> links) {
  const SimTime now = scheduler_.now();
  retire(now);
  // Every frame counts here, far links or not: a reception of it rebuilds its interference back
  // to its detection, so far frames are kept for the longest frame's length (retire).
  longest_duration_ = std::max(longest_duration_, duration);
  if (links->far_by_receiver.empty()) return;
  // Links are in arrival order: the last one has the longest delay.
  const SimTime reach = links->links.back().delay;
  longest_reach_ = std::max(longest_reach_, reach);
  const std::uint64_t oldest = oldest_number();
  AirFrame frame{
      uid, now, duration, now + reach + duration, first_sequence, std::move(links), next_number_++};
  for (const FarLink& far : frame.links->far_by_receiver) {
    Receiver& r = receivers_[far.receiver];
    r.pending_units += far.units;
    if (!r.hot && r.pending_units >= hot_units_) begin_events(far.receiver);  // this one follows
    if (r.hot) frame.links->links[far.link].phy->far_signal_event(signal_of(frame, far.link));
    // After begin_events, which hands over the kept frames: this one is not kept yet.
    remember_at(r, oldest, FarEntry{frame.number, far.link});
  }
  frames_.push_back(std::move(frame));
}

void FarSignals::retire(SimTime now) {
  // Every frame whose far signals have all ended gives its units back, in any order.
  for (std::size_t i = counted_from_; i < frames_.size(); ++i) {
    AirFrame& frame = frames_[i];
    if (!frame.counted || frame.last_end >= now) continue;
    frame.counted = false;
    for (const FarLink& far : frame.links->far_by_receiver) {
      Receiver& r = receivers_[far.receiver];
      r.pending_units -= far.units;
      if (r.hot && !r.held && r.pending_units < hot_units_) end_events(far.receiver);
    }
  }
  while (counted_from_ < frames_.size() && !frames_[counted_from_].counted) ++counted_from_;
  // Kept while a question can reach them: far_starts looks kFarStartHistory back, a reception's
  // rebuild to its start.
  const SimTime keep = std::max(kFarStartHistory, longest_duration_ + longest_reach_);
  while (!frames_.empty() && !frames_.front().counted && frames_.front().last_end + keep < now) {
    frames_.pop_front();
    --counted_from_;
  }
}

void FarSignals::begin_events(NodeId receiver) {
  Receiver& r = receivers_[receiver];
  // Every far signal it was not handed that ends after the PHY's history starts: those still
  // to end become events, and a reception under way needs the others' past too.
  const EventKey horizon = phys_[receiver]->far_history_start();
  std::vector<FarSignal>& signals = scratch_;
  signals.clear();
  for_each_far_frame(receiver, SimTime::min(), horizon.time,
                     [&](const AirFrame& frame, std::size_t index) {
                       const FarSignal signal = signal_of(frame, index);
                       if (horizon < signal.end) signals.push_back(signal);
                     });
  std::sort(signals.begin(), signals.end(), by_start);
  // Hot only after: the PHY first replays the windows of those that already started, which
  // far_starts must still list.
  phys_[receiver]->begin_far_events(signals);
  r.hot = true;
}

void FarSignals::end_events(NodeId receiver) {
  Receiver& r = receivers_[receiver];
  r.hot = false;
  r.lazy_from = next_number_;
  phys_[receiver]->end_far_events();
}

void FarSignals::hold_far_events(NodeId receiver, bool hold) {
  Receiver& r = receivers_[receiver];
  if (r.held == hold) return;
  r.held = hold;
  if (hold && !r.hot) begin_events(receiver);
  if (!hold && r.hot && r.pending_units < hot_units_) end_events(receiver);
}

template <typename F>
void FarSignals::for_each_far_frame(NodeId receiver, SimTime sent_from, SimTime ends_after,
                                    F&& f) const {
  const Receiver& r = receivers_[receiver];
  if (r.hot) return;  // every far signal was handed over
  const std::uint64_t oldest = oldest_number();
  for (std::size_t i = r.frames.size(); i-- > 0;) {
    const FarEntry entry = r.frames[i];
    // Handed over (below lazy_from) or no longer kept: so is every earlier one.
    if (entry.number < r.lazy_from || entry.number < oldest) break;
    const AirFrame& frame = frames_[entry.number - oldest];
    if (frame.sent < sent_from) break;
    if (frame.last_end < ends_after) continue;  // over everywhere
    f(frame, entry.link);
  }
}

void FarSignals::far_starts(NodeId receiver, EventKey from, EventKey to,
                            std::vector<FarSignal>& out) const {
  const std::size_t first = out.size();
  // A frame's signals start at most longest_reach_ after it was sent.
  for_each_far_frame(receiver, from.time - longest_reach_, from.time,
                     [&](const AirFrame& frame, std::size_t index) {
                       const FarSignal signal = signal_of(frame, index);
                       if (from < signal.start && signal.start < to) out.push_back(signal);
                     });
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), by_start);
}

void FarSignals::far_signals_during(NodeId receiver, EventKey from, EventKey to,
                                    std::vector<FarSignal>& out) const {
  for_each_far_frame(receiver, from.time - longest_reach_ - longest_duration_, from.time,
                     [&](const AirFrame& frame, std::size_t index) {
                       const FarSignal signal = signal_of(frame, index);
                       if (signal.start < to && from < signal.end) out.push_back(signal);
                     });
}

}  // namespace swarmnet
