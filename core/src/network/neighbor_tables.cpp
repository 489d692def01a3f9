#include "network/neighbor_tables.hpp"

#include <algorithm>

namespace swarmnet {

NeighborTables::NeighborTables(std::uint32_t nodes, const NeighborSensing& settings)
    : window_(from_seconds(settings.window_s)),
      max_per_robot_(settings.max_per_robot),
      smoothing_(settings.rssi_smoothing),
      tables_(nodes) {}

void NeighborTables::heard(NodeId receiver, const Frame& frame, const RxInfo& info, SimTime now) {
  if (frame.type == FrameType::ack || frame.type == FrameType::cts) return;
  if (receiver >= tables_.size() || frame.transmitter == receiver) return;
  std::vector<Heard>& table = tables_[receiver];
  auto at = std::lower_bound(table.begin(), table.end(), frame.transmitter,
                             [](const Heard& h, NodeId id) { return h.reading.id < id; });
  if (at == table.end() || at->reading.id != frame.transmitter) {
    Heard fresh;
    fresh.reading.id = frame.transmitter;
    fresh.reading.rssi_smoothed_dbm = info.rx_power_dbm;
    at = table.insert(at, std::move(fresh));
  } else {
    RadioNeighbor& r = at->reading;
    r.rssi_smoothed_dbm += smoothing_ * (info.rx_power_dbm - r.rssi_smoothed_dbm);
  }
  RadioNeighbor& r = at->reading;
  r.last_heard = now;
  r.rssi_dbm = info.rx_power_dbm;
  r.sinr_db = info.sinr_db;
  at->frame_ends.push_back(now);
}

void NeighborTables::collect(SimTime now, std::vector<std::uint32_t>& counts,
                             std::vector<RadioNeighbor>& entries) {
  counts.assign(tables_.size(), 0);
  entries.clear();
  const SimTime cutoff = now - window_;
  for (std::size_t node = 0; node < tables_.size(); ++node) {
    std::vector<Heard>& table = tables_[node];
    // Age out: a neighbour silent for the whole window leaves; old frames stop counting.
    std::erase_if(table, [cutoff](const Heard& h) { return h.reading.last_heard <= cutoff; });
    for (Heard& h : table) {
      const auto first_inside = std::upper_bound(h.frame_ends.begin(), h.frame_ends.end(), cutoff);
      h.frame_ends.erase(h.frame_ends.begin(), first_inside);
      h.reading.frames = static_cast<std::uint32_t>(h.frame_ends.size());
    }
    kept_.resize(table.size());
    for (std::uint32_t i = 0; i < kept_.size(); ++i) kept_[i] = i;
    if (kept_.size() > max_per_robot_) {
      std::nth_element(kept_.begin(), kept_.begin() + max_per_robot_, kept_.end(),
                       [&table](std::uint32_t a, std::uint32_t b) {
                         const SimTime ta = table[a].reading.last_heard;
                         const SimTime tb = table[b].reading.last_heard;
                         return ta != tb ? ta > tb : a < b;  // ascending index = ascending id
                       });
      kept_.resize(max_per_robot_);
      std::sort(kept_.begin(), kept_.end());
    }
    counts[node] = static_cast<std::uint32_t>(kept_.size());
    for (const std::uint32_t i : kept_) entries.push_back(table[i].reading);
  }
}

}  // namespace swarmnet
