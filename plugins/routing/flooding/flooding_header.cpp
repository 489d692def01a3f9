#include "flooding_header.hpp"

namespace swarmnet::flooding {

namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (unsigned shift = 0; shift < 32; shift += 8) {
    out.push_back(static_cast<std::uint8_t>(value >> shift));
  }
}

std::uint32_t get_u32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (unsigned i = 0; i < 4; ++i) {
    value |= static_cast<std::uint32_t>(bytes[offset + i]) << (8U * i);
  }
  return value;
}

}  // namespace

void encode(const FloodingHeader& header, std::vector<std::uint8_t>& out) {
  out.clear();
  out.reserve(FloodingHeader::kSize);
  put_u32(out, header.originator);
  put_u32(out, header.sequence);
  out.push_back(header.ttl);
}

std::vector<std::uint8_t> encode(const FloodingHeader& header) {
  std::vector<std::uint8_t> out;
  encode(header, out);
  return out;
}

std::optional<FloodingHeader> decode(std::span<const std::uint8_t> bytes) {
  if (bytes.size() != FloodingHeader::kSize) return std::nullopt;
  FloodingHeader header;
  header.originator = get_u32(bytes, 0);
  header.sequence = get_u32(bytes, 4);
  header.ttl = bytes[8];
  return header;
}

}  // namespace swarmnet::flooding
