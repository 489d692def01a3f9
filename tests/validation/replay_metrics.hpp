// What the ns-3 replay measures, with the definitions of SwarmNet's summary.json
// (core/src/network/network_metrics.hpp) so that the two can be compared field by field:
//   sent        application messages injected (unicast and broadcast)
//   delivered   unicast messages that reached their destination's application at least once
//   pdr         delivered / unicast sent
//   delay_s     over the first delivery of each unicast message: mean, p50, p95 (nearest rank)
//   hops_mean   over the same deliveries
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "traffic_csv.hpp"

namespace swarmnet::validation {

class ReplayMetrics {
 public:
  // `messages` is the traffic schedule; a message is named by its index in it.
  explicit ReplayMetrics(const std::vector<TrafficMessage>& messages);

  void message_sent(std::uint32_t index);
  // The application of `node` received message `index` at `now_ns`, after `hops` links.
  void message_received(std::uint32_t index, std::uint32_t node, std::int64_t now_ns,
                        std::uint32_t hops);

  [[nodiscard]] nlohmann::ordered_json report() const;
  // One CSV line per message of the schedule, with a header:
  // message_id,source,destination,inject_ns,delivered_ns (destination -1: broadcast;
  // delivered_ns: first delivery at the destination, -1 if none).
  void write_deliveries(std::ostream& out) const;

 private:
  const std::vector<TrafficMessage>& messages_;
  std::vector<std::int64_t> first_delivery_ns_;  // per message; -1 until delivered
  std::uint64_t sent_ = 0;
  std::uint64_t broadcast_sent_ = 0;
  std::uint64_t broadcast_deliveries_ = 0;
  std::uint64_t duplicates_ = 0;
  std::uint64_t misdelivered_ = 0;
  std::vector<std::int64_t> delays_ns_;
  std::uint64_t hops_total_ = 0;
};

}  // namespace swarmnet::validation
