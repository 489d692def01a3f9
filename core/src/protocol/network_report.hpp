// The network half's account of a whole run: sent once after the last step (the report record)
// and turned into summary.json's network part by the outputs room (outputs/run_summary.hpp).
// Definitions of every field: network/network_metrics.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swarmnet {

struct NamedCount {
  std::string name;
  std::uint64_t value = 0;

  bool operator==(const NamedCount&) const = default;
};

struct NetworkReport {
  std::uint64_t sent = 0;
  std::uint64_t delivered = 0;
  std::vector<NamedCount> dropped;  // one per drop reason, in the summary's order
  std::uint64_t broadcast_sent = 0;
  std::uint64_t broadcast_deliveries = 0;
  std::uint64_t undelivered = 0;  // unicast messages not delivered (network_metrics.hpp)
  std::uint64_t duplicates = 0;
  double pdr = 0.0;
  // Over the first delivery of each unicast message; absent when none was delivered.
  std::optional<double> delay_mean_s;
  std::optional<double> delay_p50_s;
  std::optional<double> delay_p95_s;
  std::optional<double> hops_mean;
  std::vector<NamedCount> mac;      // in the summary's order
  std::vector<NamedCount> routing;  // in the summary's order
  std::vector<NamedCount> arp;      // in the summary's order
  std::uint64_t events = 0;
  // CPU the network half spent simulating and on the transport; filled by the half, not the
  // simulator, and zero in a replay's report.
  double network_cpu_s = 0.0;
  double transport_cpu_s = 0.0;

  bool operator==(const NetworkReport&) const = default;
};

}  // namespace swarmnet
