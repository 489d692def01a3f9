#include "network/neighbor_tables.hpp"

#include <algorithm>

namespace swarmnet {

NeighborTables::NeighborTables(std::uint32_t nodes, const NeighborSensing& settings)
    : window_(from_seconds(settings.window_s)),
      max_per_robot_(settings.max_per_robot),
      smoothing_(settings.rssi_smoothing),
      tables_(nodes),
      links_(nodes) {}

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

void NeighborTables::exchange_ended(NodeId sender, NodeId next_hop, bool acknowledged,
                                    std::uint32_t attempts, SimTime now) {
  if (sender >= links_.size() || next_hop >= links_.size() || next_hop == sender) return;
  std::vector<Link>& links = links_[sender];
  auto at = std::lower_bound(links.begin(), links.end(), next_hop,
                             [](const Link& l, NodeId id) { return l.neighbor < id; });
  if (at == links.end() || at->neighbor != next_hop) at = links.insert(at, Link{next_hop, {}});
  at->exchanges.push_back(Exchange{now, acknowledged && attempts == 1});
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
      h.reading.unicasts = 0;
      h.reading.first_attempt_acks = 0;
    }
    count_exchanges(node, cutoff);
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

void NeighborTables::count_exchanges(std::size_t node, SimTime cutoff) {
  std::vector<Link>& links = links_[node];
  for (Link& link : links) {
    std::erase_if(link.exchanges, [cutoff](const Exchange& e) { return e.ended <= cutoff; });
  }
  std::erase_if(links, [](const Link& l) { return l.exchanges.empty(); });
  // Both ascending by id: one merge walk.
  std::vector<Heard>& table = tables_[node];
  auto heard = table.begin();
  for (const Link& link : links) {
    while (heard != table.end() && heard->reading.id < link.neighbor) ++heard;
    if (heard == table.end()) return;
    if (heard->reading.id != link.neighbor) continue;
    heard->reading.unicasts = static_cast<std::uint32_t>(link.exchanges.size());
    heard->reading.first_attempt_acks = static_cast<std::uint32_t>(
        std::count_if(link.exchanges.begin(), link.exchanges.end(),
                      [](const Exchange& e) { return e.first_attempt_ack; }));
  }
}

}  // namespace swarmnet
