#include "replay_metrics.hpp"

#include <algorithm>

namespace swarmnet::validation {

namespace {

// Nearest-rank percentile of sorted, non-empty samples, exactly as SwarmNet computes it.
std::int64_t nearest_rank(const std::vector<std::int64_t>& sorted, std::size_t percent) {
  std::size_t rank = (percent * sorted.size() + 99) / 100;
  rank = std::clamp<std::size_t>(rank, 1, sorted.size());
  return sorted[rank - 1];
}

}  // namespace

ReplayMetrics::ReplayMetrics(const std::vector<TrafficMessage>& messages)
    : messages_(messages), first_delivery_ns_(messages.size(), -1) {}

void ReplayMetrics::message_sent(std::uint32_t index) {
  ++sent_;
  if (messages_[index].broadcast()) ++broadcast_sent_;
}

void ReplayMetrics::message_received(std::uint32_t index, std::uint32_t node, std::int64_t now_ns,
                                     std::uint32_t hops) {
  const TrafficMessage& message = messages_[index];
  if (message.broadcast()) {
    if (node != message.source) ++broadcast_deliveries_;
    return;
  }
  if (node != message.destination) {
    ++misdelivered_;
    return;
  }
  if (first_delivery_ns_[index] >= 0) {
    ++duplicates_;
    return;
  }
  first_delivery_ns_[index] = now_ns;
  delays_ns_.push_back(now_ns - message.inject_ns);
  hops_total_ += hops;
}

nlohmann::ordered_json ReplayMetrics::report() const {
  using Json = nlohmann::ordered_json;
  Json out;
  const std::uint64_t delivered = delays_ns_.size();
  const std::uint64_t unicast = sent_ - broadcast_sent_;
  out["packets"] = {{"sent", sent_},
                    {"delivered", delivered},
                    {"broadcast_sent", broadcast_sent_},
                    {"broadcast_deliveries", broadcast_deliveries_},
                    {"duplicates", duplicates_},
                    {"misdelivered", misdelivered_}};
  out["pdr"] = unicast == 0 ? 0.0 : static_cast<double>(delivered) / static_cast<double>(unicast);
  if (delays_ns_.empty()) {
    out["delay_s"] = {{"mean", nullptr}, {"p50", nullptr}, {"p95", nullptr}};
    out["hops_mean"] = nullptr;
    return out;
  }
  std::vector<std::int64_t> sorted = delays_ns_;
  std::sort(sorted.begin(), sorted.end());
  std::int64_t total_ns = 0;
  for (const std::int64_t d : sorted) total_ns += d;
  const auto n = static_cast<double>(sorted.size());
  out["delay_s"] = {{"mean", static_cast<double>(total_ns) * 1e-9 / n},
                    {"p50", static_cast<double>(nearest_rank(sorted, 50)) * 1e-9},
                    {"p95", static_cast<double>(nearest_rank(sorted, 95)) * 1e-9}};
  out["hops_mean"] = static_cast<double>(hops_total_) / n;
  return out;
}

void ReplayMetrics::write_deliveries(std::ostream& out) const {
  out << "message_id,source,destination,inject_ns,delivered_ns\n";
  for (std::size_t i = 0; i < messages_.size(); ++i) {
    const TrafficMessage& message = messages_[i];
    out << message.message_id << ',' << message.source << ','
        << (message.broadcast() ? std::int64_t{-1} : std::int64_t{message.destination}) << ','
        << message.inject_ns << ',' << first_delivery_ns_[i] << '\n';
  }
}

}  // namespace swarmnet::validation
