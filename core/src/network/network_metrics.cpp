#include "network/network_metrics.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace swarmnet {

namespace {

constexpr std::array kDropReasons = {DropReason::no_route,       DropReason::queue_full,
                                     DropReason::ttl_expired,    DropReason::retry_limit,
                                     DropReason::buffer_timeout, DropReason::arp_queue_full,
                                     DropReason::arp_unresolved};

constexpr std::array<const char*, 4> kMacKeys = {"tx_frames", "tx_bytes", "collisions", "retries"};
constexpr std::array<const char*, 6> kArpKeys = {
    "requests_sent", "replies_sent", "resolved", "failed", "replies_ignored", "frames_dropped"};
constexpr std::array<const char*, 3> kRoutingKeys = {"control_packets", "control_bytes",
                                                     "data_forwards"};

// Nearest-rank percentile of sorted, non-empty samples: the ceil(percent / 100 * n)-th smallest,
// in integer arithmetic so that no rounding moves the rank.
std::int64_t nearest_rank(const std::vector<std::int64_t>& sorted, std::size_t percent) {
  std::size_t rank = (percent * sorted.size() + 99) / 100;
  rank = std::clamp<std::size_t>(rank, 1, sorted.size());
  return sorted[rank - 1];
}

// The counters `first` names, in that order (0 when never counted), then every other one by name.
template <std::size_t N>
std::vector<NamedCount> ordered_counters(
    const std::array<const char*, N>& first,
    const std::map<std::string, std::uint64_t, std::less<>>& counters) {
  std::vector<NamedCount> out;
  out.reserve(counters.size() + N);
  for (const char* key : first) {
    const auto it = counters.find(std::string_view(key));
    out.push_back({key, it == counters.end() ? 0 : it->second});
  }
  for (const auto& entry : counters) {
    const bool listed = std::any_of(first.begin(), first.end(),
                                    [&entry](const char* k) { return entry.first == k; });
    if (!listed) out.push_back({entry.first, entry.second});
  }
  return out;
}

}  // namespace

NetworkMetrics::NetworkMetrics() {
  for (const char* key : kMacKeys) mac_[key] = 0;
  routing_["control_packets"] = 0;
  routing_["control_bytes"] = 0;
}

void NetworkMetrics::message_sent(bool broadcast) {
  ++sent_;
  if (broadcast) ++broadcast_sent_;
}

void NetworkMetrics::unicast_delivered(SimTime delay, std::uint32_t hops) {
  delays_ns_.push_back(delay.count());
  hops_total_ += hops;
}

void NetworkMetrics::dropped(DropReason reason) { ++drops_[reason]; }

std::uint64_t NetworkMetrics::drops(DropReason reason) const {
  const auto it = drops_.find(reason);
  return it == drops_.end() ? 0 : it->second;
}

void NetworkMetrics::frame_transmitted(std::uint32_t bytes) {
  ++mac_["tx_frames"];
  mac_["tx_bytes"] += bytes;
}

void NetworkMetrics::control_packet_sent(std::uint32_t bytes) {
  ++routing_["control_packets"];
  routing_["control_bytes"] += bytes;
}

void NetworkMetrics::mac_count(std::string_view counter, std::uint64_t amount) {
  add(mac_, counter, amount);
}

void NetworkMetrics::routing_count(std::string_view counter, std::uint64_t amount) {
  add(routing_, counter, amount);
}

void NetworkMetrics::arp_count(std::string_view counter, std::uint64_t amount) {
  add(arp_, counter, amount);
}

void NetworkMetrics::add(CounterMap& counters, std::string_view counter, std::uint64_t amount) {
  if (auto it = counters.find(counter); it != counters.end()) {
    it->second += amount;
  } else {
    counters.emplace(std::string(counter), amount);
  }
}

NetworkReport NetworkMetrics::report(std::uint64_t undelivered, std::uint64_t events) const {
  NetworkReport out;
  out.sent = sent_;
  out.delivered = delivered();
  for (const DropReason reason : kDropReasons)
    out.dropped.push_back({to_string(reason), drops(reason)});
  out.broadcast_sent = broadcast_sent_;
  out.broadcast_deliveries = broadcast_deliveries_;
  out.undelivered = undelivered;
  out.duplicates = duplicates_;

  const std::uint64_t unicast = unicast_sent();
  out.pdr = unicast == 0 ? 0.0 : static_cast<double>(delivered()) / static_cast<double>(unicast);

  if (!delays_ns_.empty()) {
    std::vector<std::int64_t> sorted = delays_ns_;
    std::sort(sorted.begin(), sorted.end());
    // Integer sum (exact), then one division: the mean does not depend on summation order.
    std::int64_t total_ns = 0;
    for (const std::int64_t d : sorted) total_ns += d;
    const auto n = static_cast<double>(sorted.size());
    out.delay_mean_s = static_cast<double>(total_ns) * 1e-9 / n;
    out.delay_p50_s = to_seconds(SimTime{nearest_rank(sorted, 50)});
    out.delay_p95_s = to_seconds(SimTime{nearest_rank(sorted, 95)});
    out.hops_mean = static_cast<double>(hops_total_) / n;
  }

  out.mac = ordered_counters(kMacKeys, mac_);
  CounterMap routing = routing_;
  routing["data_forwards"] += data_forwards_;
  out.routing = ordered_counters(kRoutingKeys, routing);
  out.arp = ordered_counters(kArpKeys, arp_);
  out.events = events;
  return out;
}

}  // namespace swarmnet
