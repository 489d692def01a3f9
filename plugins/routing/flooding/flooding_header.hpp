// The flooding header, carried in Packet::header.
//
// Wire layout (9 bytes, little-endian):
//   offset 0  uint32  originator  node that sent the packet first
//   offset 4  uint32  sequence    originator's packet counter (wraps)
//   offset 8  uint8   ttl         hops the packet may still be relayed
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "swarmnet/ids.hpp"

namespace swarmnet::flooding {

struct FloodingHeader {
  NodeId originator = kNoNode;
  std::uint32_t sequence = 0;
  std::uint8_t ttl = 0;

  static constexpr std::size_t kSize = 9;

  friend bool operator==(const FloodingHeader&, const FloodingHeader&) = default;
};

// Replaces `out` by the header's bytes.
void encode(const FloodingHeader& header, std::vector<std::uint8_t>& out);
[[nodiscard]] std::vector<std::uint8_t> encode(const FloodingHeader& header);
// The header in `bytes`, or nothing if they are not exactly kSize long.
[[nodiscard]] std::optional<FloodingHeader> decode(std::span<const std::uint8_t> bytes);

}  // namespace swarmnet::flooding
