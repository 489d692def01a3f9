// Destination sequence numbers compare with rollover (RFC 3561 section 6.1): a is fresher than b
// when the signed 32-bit difference a - b is positive.
#pragma once

#include <cstdint>

namespace swarmnet::aodv {

[[nodiscard]] constexpr bool seq_newer(std::uint32_t a, std::uint32_t b) {
  return static_cast<std::int32_t>(a - b) > 0;
}
[[nodiscard]] constexpr bool seq_not_older(std::uint32_t a, std::uint32_t b) {
  return static_cast<std::int32_t>(a - b) >= 0;
}

}  // namespace swarmnet::aodv
