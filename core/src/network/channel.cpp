#include "network/channel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace swarmnet {

namespace {

// Grid cells no smaller than this: a tiny cutoff would otherwise make millions of empty cells.
constexpr double kMinCellM = 1.0;

}  // namespace

Channel::Channel(const Scenario& scenario, PropagationChain chain, Scheduler& scheduler,
                 std::size_t node_count)
    : chain_(std::move(chain)),
      scheduler_(scheduler),
      tx_power_dbm_(scenario.network.phy.tx_power_dbm + scenario.network.phy.tx_gain_db),
      rx_gain_db_(scenario.network.phy.rx_gain_db),
      cutoff_m_(cutoff_distance_m(chain_, tx_power_dbm_,
                                  audibility_threshold_dbm(scenario.network.phy) - rx_gain_db_)),
      use_grid_(scenario.network.channel.cutoff && std::isfinite(cutoff_m_)),
      phys_(node_count, nullptr),
      positions_(node_count, Vec2::Zero()),
      arena_bounds_{0.0, 0.0, scenario.arena.width_m, scenario.arena.height_m} {
  candidates_.reserve(node_count);
  rebuild_grid();
}

void Channel::attach(NodeId node, Phy& phy) { phys_.at(node) = &phy; }

void Channel::set_positions(std::span<const Vec2> positions) {
  if (positions.size() != positions_.size()) {
    throw std::invalid_argument("Channel: " + std::to_string(positions.size()) + " positions for " +
                                std::to_string(positions_.size()) + " nodes");
  }
  std::copy(positions.begin(), positions.end(), positions_.begin());
  rebuild_grid();
}

void Channel::rebuild_grid() {
  if (!use_grid_) return;
  // Bounds: the arena grown to hold every node (points outside would pile up in border cells).
  Rect bounds = arena_bounds_;
  for (const Vec2& p : positions_) {
    bounds.x_min_m = std::min(bounds.x_min_m, p.x());
    bounds.y_min_m = std::min(bounds.y_min_m, p.y());
    bounds.x_max_m = std::max(bounds.x_max_m, p.x());
    bounds.y_max_m = std::max(bounds.y_max_m, p.y());
  }
  if (!grid_ready_ || bounds != grid_bounds_) {
    grid_.reset(bounds, std::max(cutoff_m_, kMinCellM));
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
  auto shared = std::make_shared<const Frame>(std::move(frame));
  scheduler_.schedule_in(duration, [&tx_phy] { tx_phy.end_transmission(); });

  const Vec2 tx_position = positions_[transmitter];
  candidates_.clear();
  if (use_grid_) {
    if (cutoff_m_ <= 0.0) return;
    grid_.for_each_candidate(tx_position, cutoff_m_,
                             [this](std::uint32_t node) { candidates_.push_back(node); });
    std::sort(candidates_.begin(), candidates_.end());
  } else {
    for (NodeId node = 0; node < positions_.size(); ++node) candidates_.push_back(node);
  }

  for (const NodeId receiver : candidates_) {
    if (receiver == transmitter) continue;
    const Vec2& rx_position = positions_[receiver];
    const double distance_m = (rx_position - tx_position).norm();
    if (use_grid_ && distance_m >= cutoff_m_) continue;
    const RadioLink link{transmitter, receiver, tx_position, rx_position, distance_m, uid};
    const double power_dbm = chain_.rx_power_dbm(tx_power_dbm_, link) + rx_gain_db_;
    Phy* rx_phy = phys_[receiver];
    if (!rx_phy->audible(power_dbm)) continue;
    const SimTime delay = propagation_delay(distance_m);
    scheduler_.schedule_in(delay,
                           [rx_phy, uid, power_dbm] { rx_phy->signal_start(uid, power_dbm); });
    scheduler_.schedule_in(delay + duration,
                           [rx_phy, shared, power_dbm] { rx_phy->signal_end(*shared, power_dbm); });
  }
}

}  // namespace swarmnet
