#include "network/channel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "swarmnet/units.hpp"

namespace swarmnet {

namespace {

// Grid cells no smaller than this: a tiny cutoff would otherwise make millions of empty cells.
constexpr double kMinCellM = 1.0;

}  // namespace

Channel::Channel(const NetworkSettings& settings, PropagationChain chain, Scheduler& scheduler,
                 std::size_t node_count)
    : chain_(std::move(chain)),
      scheduler_(scheduler),
      tx_power_dbm_(settings.network.phy.tx_power_dbm + settings.network.phy.tx_gain_db),
      rx_gain_db_(settings.network.phy.rx_gain_db),
      audibility_dbm_(audibility_threshold_dbm(settings.network.phy)),
      event_dbm_(event_threshold_dbm(settings.network.phy)),
      cutoff_m_(cutoff_distance_m(chain_, tx_power_dbm_, audibility_dbm_ - rx_gain_db_)),
      event_cutoff_m_(event_dbm_ > audibility_dbm_
                          ? cutoff_distance_m(chain_, tx_power_dbm_, event_dbm_ - rx_gain_db_)
                          : cutoff_m_),
      use_grid_(settings.network.channel.cutoff && std::isfinite(event_cutoff_m_)),
      has_quiet_signals_(event_dbm_ > audibility_dbm_),
      cache_links_(!chain_.varies_per_frame()),
      // Far signals are found again by their step's links, kept while frames may be asked about:
      // models that draw per frame would need every frame's links kept; they keep events.
      far_lazy_(settings.network.channel.lazy_far_signals &&
                settings.network.phy.model == PhyModel::sinr && cache_links_),
      is_far_(settings.network.phy),
      phys_(node_count, nullptr),
      far_index_scratch_(node_count),
      positions_(node_count, Vec2::Zero()),
      arena_bounds_{0.0, 0.0, settings.arena.width_m, settings.arena.height_m},
      step_links_(node_count) {
  if (far_lazy_) {
    far_signals_ =
        std::make_unique<FarSignals>(scheduler_, phys_, sensing_threshold_mw(settings.network.phy));
  }
  rebuild_grid();
}

void Channel::attach(NodeId node, Phy& phy) {
  // Before the first frame only: the links a step keeps hold the receivers' PHYs.
  if (frames_sent() > 0) throw std::logic_error("Channel: a PHY attached after the first frame");
  phys_.at(node) = &phy;
  if (has_quiet_signals_) phy.set_quiet_signal_source(this, node);
  if (far_signals_) phy.set_far_signal_source(far_signals_.get(), node);
}

void Channel::set_positions(std::span<const Vec2> positions) {
  if (positions.size() != positions_.size()) {
    throw std::invalid_argument("Channel: " + std::to_string(positions.size()) + " positions for " +
                                std::to_string(positions_.size()) + " nodes");
  }
  std::copy(positions.begin(), positions.end(), positions_.begin());
  positions_snapshot_.reset();
  step_links_.assign(positions_.size(), nullptr);
  rebuild_grid();
}

void Channel::rebuild_grid() {
  // Bounds: the arena grown to hold every node (points outside would pile up in border cells).
  Rect bounds = arena_bounds_;
  for (const Vec2& p : positions_) bounds.include(p);
  // The farthest a frame sent during this step can travel: the cutoff, or else across the bounds.
  const double reach_m =
      std::isfinite(cutoff_m_) ? cutoff_m_ : std::hypot(bounds.width_m(), bounds.height_m());
  longest_reach_ = std::max(longest_reach_, propagation_delay(reach_m));
  if (!use_grid_) return;
  if (!grid_ready_ || bounds != grid_bounds_) {
    grid_.reset(bounds, std::max(event_cutoff_m_, kMinCellM));
    grid_bounds_ = bounds;
    grid_ready_ = true;
  }
  grid_.build(positions_);
}

SimTime Channel::propagation_delay(double distance_m) {
  return from_seconds(distance_m / kSpeedOfLightMps);
}

void Channel::transmit(NodeId transmitter, Frame frame, SimTime duration) {
  if (transmitter >= phys_.size() || phys_[transmitter] == nullptr) {
    throw std::logic_error("Channel: transmission from unknown node " +
                           std::to_string(transmitter));
  }
  if (duration < kTimeZero) throw std::logic_error("Channel: negative frame duration");
  Phy& tx_phy = *phys_[transmitter];
  tx_phy.start_transmission();
  frame.uid = next_frame_uid_++;
  frame.transmitter = transmitter;
  const std::uint64_t uid = frame.uid;
  scheduler_.schedule_in(duration, [&tx_phy] { tx_phy.end_transmission(); });
  if (has_quiet_signals_) remember_on_air(frame, duration);

  const std::uint32_t index = acquire_fanout();
  FrameFanout& fanout = *fanouts_[index];
  if (cache_links_) {
    std::shared_ptr<const ChannelLinks>& cached = step_links_[transmitter];
    if (!cached) {
      auto links = std::make_shared<ChannelLinks>();
      compute_links(transmitter, uid, *links);
      cached = std::move(links);
    }
    fanout.step_links = cached;
    fanout.link_set = cached.get();
  } else {
    compute_links(transmitter, uid, fanout.own_links);
    fanout.link_set = &fanout.own_links;
  }
  const std::vector<Link>& links = fanout.link_set->links;
  if (links.empty()) {
    release_fanout(index);
    return;
  }
  // Sequence numbers as if each receiver's start and end had been scheduled now, in arrival
  // order; both streams run in that order. Far links keep theirs (FarSignals hands them over).
  fanout.first_sequence = scheduler_.reserve_sequences(2 * links.size());
  if (far_signals_)
    far_signals_->frame_sent(uid, duration, fanout.first_sequence, fanout.step_links);
  if (fanout.link_set->near.empty()) {
    release_fanout(index);
    return;
  }
  fanout.frame = std::move(frame);
  fanout.sent = scheduler_.now();
  fanout.duration = duration;
  fanout.next_start = 0;
  fanout.next_end = 0;
  schedule_next<false>(index);
  schedule_next<true>(index);
}

double Channel::link_power_dbm(const RadioLink& link) const {
  return chain_.rx_power_dbm(tx_power_dbm_, link) + rx_gain_db_;
}

void Channel::compute_links(NodeId transmitter, std::uint64_t uid, ChannelLinks& link_set) const {
  link_set.clear();
  std::vector<Link>& links = link_set.links;
  const Vec2 tx_position = positions_[transmitter];
  const auto visit = [&](NodeId receiver) {
    if (receiver == transmitter) return;
    const Vec2& rx_position = positions_[receiver];
    const double distance_m = (rx_position - tx_position).norm();
    if (use_grid_ && distance_m >= event_cutoff_m_) return;
    const double power_dbm =
        link_power_dbm({transmitter, receiver, tx_position, rx_position, distance_m, uid});
    if (power_dbm < event_dbm_) return;  // inaudible, or quiet: see quiet_signals()
    const double power_mw = dbm_to_milliwatts(power_dbm);
    const bool far = far_lazy_ && is_far_(power_dbm, power_mw);
    links.push_back(Link{propagation_delay(distance_m), receiver, far, phys_[receiver], power_dbm,
                         power_mw, far ? far_signals_->units(power_mw) : 0});
  };
  if (use_grid_) {
    // In cell order: the links are sorted below, so the visit needs no order of its own.
    if (event_cutoff_m_ > 0.0) grid_.for_each_candidate(tx_position, event_cutoff_m_, visit);
  } else {
    for (NodeId node = 0; node < positions_.size(); ++node) visit(node);
  }
  // Arrival order; receivers at the same distance by id. Sorted as one 64-bit key per link, the
  // delay above the receiver, then the links gathered in that order: moving 48-byte links in the
  // sort cost more than the sort itself, and one integer compares faster than a pair.
  std::vector<std::uint64_t>& keys = arrival_keys_;
  std::vector<std::uint32_t>& link_of = far_index_scratch_.link_of_receiver;  // index_far's too
  keys.clear();
  bool packed = true;
  for (std::uint32_t i = 0; i < links.size(); ++i) {
    const auto delay = static_cast<std::uint64_t>(links[i].delay.count());
    packed = packed && delay <= std::numeric_limits<std::uint32_t>::max();
    keys.push_back(delay << 32U | links[i].receiver);
    link_of[links[i].receiver] = i;
  }
  const auto receiver_of = [](std::uint64_t key) { return static_cast<NodeId>(key); };
  if (packed) {
    std::sort(keys.begin(), keys.end());
  } else {
    // Delays of 4.3 s and more (nodes a million km apart), or negative ones from positions that
    // are not finite, do not fit: compare the links' own.
    std::sort(keys.begin(), keys.end(), [&](std::uint64_t a, std::uint64_t b) {
      const SimTime delay_a = links[link_of[receiver_of(a)]].delay;
      const SimTime delay_b = links[link_of[receiver_of(b)]].delay;
      return delay_a != delay_b ? delay_a < delay_b : receiver_of(a) < receiver_of(b);
    });
  }
  std::vector<Link>& sorted = sorted_links_;
  sorted.clear();
  for (const std::uint64_t key : keys) sorted.push_back(links[link_of[receiver_of(key)]]);
  links.swap(sorted);
  link_set.index_near();
  if (far_lazy_) link_set.index_far(far_index_scratch_);
}

void Channel::remember_on_air(const Frame& frame, SimTime duration) {
  const SimTime now = scheduler_.now();
  if (!positions_snapshot_) {
    positions_snapshot_ = std::make_shared<const std::vector<Vec2>>(positions_);
  }
  longest_duration_ = std::max(longest_duration_, duration);
  // A query asks about [from, now) with `from` no earlier than the start of a reception still
  // under way: at most the longest frame plus the longest reach ago. Older frames cannot matter.
  const SimTime horizon = now - longest_duration_ - longest_reach_;
  while (!on_air_.empty() &&
         on_air_.front().sent + on_air_.front().duration + longest_reach_ < horizon) {
    on_air_.pop_front();
  }
  on_air_.push_back(OnAir{frame.uid, frame.transmitter, now, duration, positions_snapshot_});
}

void Channel::quiet_signals(NodeId receiver, SimTime from, SimTime to,
                            std::vector<QuietSignal>& out) const {
  const double cutoff_squared = cutoff_m_ * cutoff_m_;
  for (const OnAir& frame : on_air_) {
    if (frame.sent >= to) break;  // sent in order: every later one starts later still
    if (frame.transmitter == receiver) continue;
    if (frame.sent + frame.duration + longest_reach_ <= from) continue;
    const std::vector<Vec2>& positions = *frame.positions;
    const Vec2& tx_position = positions[frame.transmitter];
    const Vec2& rx_position = positions[receiver];
    const Vec2 offset = rx_position - tx_position;
    if (use_grid_ && offset.squaredNorm() >= cutoff_squared) continue;
    // The link exactly as transmit() would have computed it.
    const double distance_m = offset.norm();
    if (use_grid_ && distance_m >= cutoff_m_) continue;
    const SimTime start = frame.sent + propagation_delay(distance_m);
    const SimTime end = start + frame.duration;
    if (start >= to || end <= from) continue;
    const double power_dbm = link_power_dbm(
        {frame.transmitter, receiver, tx_position, rx_position, distance_m, frame.uid});
    if (power_dbm < audibility_dbm_ || power_dbm >= event_dbm_) continue;
    out.push_back(QuietSignal{start, end, dbm_to_milliwatts(power_dbm)});
  }
}

std::uint32_t Channel::acquire_fanout() {
  if (!free_fanouts_.empty()) {
    const std::uint32_t index = free_fanouts_.back();
    free_fanouts_.pop_back();
    return index;
  }
  fanouts_.push_back(std::make_unique<FrameFanout>());
  return static_cast<std::uint32_t>(fanouts_.size() - 1);
}

void Channel::release_fanout(std::uint32_t index) {
  fanouts_[index]->step_links.reset();
  free_fanouts_.push_back(index);
}

template <bool kEnds>
void Channel::schedule_next(std::uint32_t index) {
  const FrameFanout& fanout = *fanouts_[index];
  const std::size_t i = fanout.link_set->near[kEnds ? fanout.next_end : fanout.next_start];
  scheduler_.schedule_reserved(
      fanout.step_time<kEnds>(i), fanout.step_sequence<kEnds>(i), [this, index] {
        // Steps that are due next are run here, without a round trip through the heap.
        FrameFanout& f = *fanouts_[index];
        std::size_t& next = kEnds ? f.next_end : f.next_start;
        const std::vector<std::uint32_t>& near = f.link_set->near;
        while (true) {
          const std::size_t i = near[next];
          const Link& link = f.link_set->links[i];
          ++next;
          Phy& phy = *link.phy;
          if constexpr (kEnds) {
            phy.signal_end(f.frame, link.power_dbm);
          } else {
            phy.signal_start(f.frame.uid, link.power_dbm, link.power_mw, f.step_sequence<false>(i));
          }
          if (next == near.size()) {
            // Recycled only after the last end: the receivers' callbacks read the frame.
            if constexpr (kEnds) release_fanout(index);
            return;
          }
          const std::size_t following = near[next];
          if (!scheduler_.advance_if_next(f.step_time<kEnds>(following),
                                          f.step_sequence<kEnds>(following))) {
            break;
          }
        }
        schedule_next<kEnds>(index);
      });
}

}  // namespace swarmnet
