// One replayed robot's network endpoint in ns-3: it injects the messages of the traffic schedule
// whose source it is and reports every message its application receives.
//
// A message is named by its index in the schedule, written in the first 4 bytes of its payload
// (little-endian), so no byte is added to what SwarmNet sends: the payload size is the schedule's.
#pragma once

#include <ns3/ipv4-address.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "replay_metrics.hpp"
#include "traffic_csv.hpp"

namespace swarmnet::validation {

inline constexpr std::size_t kMessageIndexBytes = 4;

// What every endpoint shares: the schedule, the metrics and the nodes' addresses.
struct ReplayWorld {
  const std::vector<TrafficMessage>& messages;
  ReplayMetrics& metrics;
  std::vector<ns3::Ipv4Address> addresses;  // by node id
  std::uint16_t port = 9;
};

class ReplayEndpoint {
 public:
  ReplayEndpoint() = default;
  ReplayEndpoint(const ReplayEndpoint&) = delete;
  ReplayEndpoint& operator=(const ReplayEndpoint&) = delete;
  ReplayEndpoint(ReplayEndpoint&&) = delete;
  ReplayEndpoint& operator=(ReplayEndpoint&&) = delete;
  virtual ~ReplayEndpoint() = default;

  // Hands message `index` (whose source is this endpoint's node) to the network now.
  virtual void send(std::uint32_t index) = 0;
};

// Appends the payload of message `index`: `payload_bytes` bytes, the index first.
inline void append_payload(std::vector<std::uint8_t>& out, std::uint32_t index,
                           std::uint32_t payload_bytes) {
  const std::size_t start = out.size();
  out.resize(start + payload_bytes, 0);
  for (std::size_t i = 0; i < kMessageIndexBytes; ++i) {
    out[start + i] = static_cast<std::uint8_t>(index >> (8U * i));
  }
}

// The message index carried by the `size` bytes at `payload`, or nothing if it is too short or
// names no message.
inline std::optional<std::uint32_t> payload_index(const std::uint8_t* payload, std::size_t size,
                                                  std::size_t message_count) {
  if (size < kMessageIndexBytes) return std::nullopt;
  std::uint32_t index = 0;
  for (std::size_t i = 0; i < kMessageIndexBytes; ++i) {
    index |= static_cast<std::uint32_t>(payload[i]) << (8U * i);
  }
  if (index >= message_count) return std::nullopt;
  return index;
}

}  // namespace swarmnet::validation
