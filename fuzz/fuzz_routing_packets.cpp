// libFuzzer target: the AODV and flooding headers as they arrive from other nodes. decode() must
// return nothing for a malformed header, and a decoded header must encode back to bytes that
// decode to the same message.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "aodv_packet.hpp"
#include "flooding_header.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  if (const auto message = swarmnet::aodv::decode(bytes)) {
    std::vector<std::uint8_t> again;
    swarmnet::aodv::encode(*message, again);
    if (!swarmnet::aodv::decode(again)) __builtin_trap();
  }
  if (const auto header = swarmnet::flooding::decode(bytes)) {
    std::vector<std::uint8_t> again;
    swarmnet::flooding::encode(*header, again);
    const auto back = swarmnet::flooding::decode(again);
    if (!back || back->originator != header->originator || back->sequence != header->sequence ||
        back->ttl != header->ttl) {
      __builtin_trap();
    }
  }
  return 0;
}
