#include "aodv_packet.hpp"

namespace swarmnet::aodv {

namespace {

constexpr std::uint8_t kFlagJ = 0x80;
constexpr std::uint8_t kFlagR = 0x40;
constexpr std::uint8_t kFlagG = 0x20;
constexpr std::uint8_t kFlagD = 0x10;
constexpr std::uint8_t kFlagU = 0x08;
constexpr std::uint8_t kRrepFlagR = 0x80;
constexpr std::uint8_t kRrepFlagA = 0x40;
constexpr std::uint8_t kRerrFlagN = 0x80;
constexpr std::uint8_t kPrefixMask = 0x1f;

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) {
    out.push_back(static_cast<std::uint8_t>(value >> static_cast<unsigned>(shift)));
  }
}

std::uint32_t get_u32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) value = (value << 8U) | bytes[offset + i];
  return value;
}

std::uint8_t flag(bool set, std::uint8_t bit) { return set ? bit : std::uint8_t{0}; }
bool has(std::uint8_t flags, std::uint8_t bit) { return (flags & bit) != 0; }

}  // namespace

void encode(const Rreq& m, std::vector<std::uint8_t>& out) {
  out.clear();
  out.reserve(Rreq::kSize);
  out.push_back(static_cast<std::uint8_t>(MessageType::rreq));
  out.push_back(static_cast<std::uint8_t>(
      flag(m.join, kFlagJ) | flag(m.repair, kFlagR) | flag(m.gratuitous, kFlagG) |
      flag(m.destination_only, kFlagD) | flag(m.unknown_seq, kFlagU)));
  out.push_back(m.ttl);
  out.push_back(m.hop_count);
  put_u32(out, m.id);
  put_u32(out, m.destination);
  put_u32(out, m.destination_seq);
  put_u32(out, m.originator);
  put_u32(out, m.originator_seq);
}

void encode(const Rrep& m, std::vector<std::uint8_t>& out) {
  out.clear();
  out.reserve(Rrep::kSize);
  out.push_back(static_cast<std::uint8_t>(MessageType::rrep));
  out.push_back(static_cast<std::uint8_t>(flag(m.repair, kRrepFlagR) |
                                          flag(m.ack_required, kRrepFlagA) |
                                          (m.prefix_size & kPrefixMask)));
  out.push_back(m.ttl);
  out.push_back(m.hop_count);
  put_u32(out, m.destination);
  put_u32(out, m.destination_seq);
  put_u32(out, m.originator);
  put_u32(out, m.lifetime_ms);
}

void encode(const Rerr& m, std::vector<std::uint8_t>& out) {
  out.clear();
  out.reserve(m.size());
  out.push_back(static_cast<std::uint8_t>(MessageType::rerr));
  out.push_back(flag(m.no_delete, kRerrFlagN));
  out.push_back(0);
  out.push_back(static_cast<std::uint8_t>(m.destinations.size()));
  for (const UnreachableDestination& d : m.destinations) {
    put_u32(out, d.destination);
    put_u32(out, d.seq);
  }
}

void encode(const RrepAck& /*m*/, std::vector<std::uint8_t>& out) {
  out.assign({static_cast<std::uint8_t>(MessageType::rrep_ack), 0});
}

void encode(const Message& message, std::vector<std::uint8_t>& out) {
  std::visit([&out](const auto& m) { encode(m, out); }, message);
}

std::vector<std::uint8_t> encode(const Message& message) {
  std::vector<std::uint8_t> out;
  encode(message, out);
  return out;
}

std::optional<Message> decode(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return std::nullopt;
  switch (static_cast<MessageType>(bytes[0])) {
    case MessageType::rreq: {
      if (bytes.size() != Rreq::kSize) return std::nullopt;
      Rreq m;
      m.join = has(bytes[1], kFlagJ);
      m.repair = has(bytes[1], kFlagR);
      m.gratuitous = has(bytes[1], kFlagG);
      m.destination_only = has(bytes[1], kFlagD);
      m.unknown_seq = has(bytes[1], kFlagU);
      m.ttl = bytes[2];
      m.hop_count = bytes[3];
      m.id = get_u32(bytes, 4);
      m.destination = get_u32(bytes, 8);
      m.destination_seq = get_u32(bytes, 12);
      m.originator = get_u32(bytes, 16);
      m.originator_seq = get_u32(bytes, 20);
      return m;
    }
    case MessageType::rrep: {
      if (bytes.size() != Rrep::kSize) return std::nullopt;
      Rrep m;
      m.repair = has(bytes[1], kRrepFlagR);
      m.ack_required = has(bytes[1], kRrepFlagA);
      m.prefix_size = static_cast<std::uint8_t>(bytes[1] & kPrefixMask);
      m.ttl = bytes[2];
      m.hop_count = bytes[3];
      m.destination = get_u32(bytes, 4);
      m.destination_seq = get_u32(bytes, 8);
      m.originator = get_u32(bytes, 12);
      m.lifetime_ms = get_u32(bytes, 16);
      return m;
    }
    case MessageType::rerr: {
      if (bytes.size() < 4) return std::nullopt;
      const std::size_t count = bytes[3];
      if (count == 0 || bytes.size() != 4 + 8 * count) return std::nullopt;
      Rerr m;
      m.no_delete = has(bytes[1], kRerrFlagN);
      for (std::size_t i = 0; i < count; ++i) {
        m.destinations.push_back({get_u32(bytes, 4 + 8 * i), get_u32(bytes, 8 + 8 * i)});
      }
      return m;
    }
    case MessageType::rrep_ack:
      if (bytes.size() != RrepAck::kSize) return std::nullopt;
      return RrepAck{};
  }
  return std::nullopt;
}

}  // namespace swarmnet::aodv
