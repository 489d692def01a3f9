// Reads a SwarmNet traffic schedule (run/traffic_schedule.hpp), the application messages to replay:
//   message_id,step,inject_ns,source,destination,payload_bytes
// destination is a robot id or "broadcast".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace swarmnet::validation {

inline constexpr std::uint32_t kBroadcastDestination = 0xFFFFFFFFU;

struct TrafficMessage {
  std::uint64_t message_id = 0;
  std::int64_t inject_ns = 0;
  std::uint32_t source = 0;
  std::uint32_t destination = kBroadcastDestination;
  std::uint32_t payload_bytes = 0;

  [[nodiscard]] bool broadcast() const { return destination == kBroadcastDestination; }
};

// Every message of the file, in file order. Throws std::runtime_error naming the file and line on
// a malformed line or a missing file.
[[nodiscard]] std::vector<TrafficMessage> read_traffic_csv(const std::string& path);

}  // namespace swarmnet::validation
