#include "task_message.hpp"

#include <bit>
#include <cmath>

namespace swarmnet::task_allocation {

namespace {

class Writer {
 public:
  explicit Writer(std::vector<std::byte>& out) : out_(out) {}
  void u8(std::uint8_t v) { out_.push_back(static_cast<std::byte>(v)); }
  void u16(std::uint16_t v) { little(v, 2); }
  void u32(std::uint32_t v) { little(v, 4); }
  void f64(double v) { little(std::bit_cast<std::uint64_t>(v), 8); }

 private:
  void little(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out_.push_back(static_cast<std::byte>((v >> (8U * i)) & 0xFFU));
  }
  std::vector<std::byte>& out_;
};

class Reader {
 public:
  explicit Reader(std::span<const std::byte> in) : in_(in) {}
  std::uint8_t u8() { return static_cast<std::uint8_t>(little(1)); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(little(2)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(little(4)); }
  double f64() { return std::bit_cast<double>(little(8)); }

 private:
  std::uint64_t little(int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) {
      v |= static_cast<std::uint64_t>(std::to_integer<std::uint8_t>(in_[at_++])) << (8U * i);
    }
    return v;
  }
  std::span<const std::byte> in_;
  std::size_t at_ = 0;
};

bool known_type(std::uint8_t byte) {
  switch (static_cast<MessageType>(byte)) {
    case MessageType::status:
    case MessageType::going:
    case MessageType::cancelled:
    case MessageType::handling:
    case MessageType::abandoning:
      return true;
  }
  return false;
}

}  // namespace

std::string_view letter(MessageType type) {
  switch (type) {
    case MessageType::status:
      return "S";
    case MessageType::going:
      return "G";
    case MessageType::cancelled:
      return "C";
    case MessageType::handling:
      return "H";
    case MessageType::abandoning:
      return "A";
  }
  return "?";
}

std::vector<std::byte> encode(const TaskMessage& message) {
  std::vector<std::byte> out;
  out.reserve(kTaskMessageBytes);
  Writer w(out);
  w.u8(static_cast<std::uint8_t>(message.type));
  w.u32(message.event_id);
  w.f64(message.event_position.x());
  w.f64(message.event_position.y());
  w.u16(message.required);
  w.u16(message.skill);
  w.u16(message.waiting);
  w.f64(message.sender_position.x());
  w.f64(message.sender_position.y());
  return out;
}

std::optional<TaskMessage> decode(std::span<const std::byte> payload) {
  if (payload.size() != kTaskMessageBytes) return std::nullopt;
  Reader r(payload);
  const std::uint8_t type = r.u8();
  if (!known_type(type)) return std::nullopt;
  TaskMessage m;
  m.type = static_cast<MessageType>(type);
  m.event_id = r.u32();
  const double event_x = r.f64();
  const double event_y = r.f64();
  m.event_position = Vec2(event_x, event_y);
  m.required = r.u16();
  m.skill = r.u16();
  m.waiting = r.u16();
  const double sender_x = r.f64();
  const double sender_y = r.f64();
  m.sender_position = Vec2(sender_x, sender_y);
  if (!m.event_position.allFinite() || !m.sender_position.allFinite()) return std::nullopt;
  return m;
}

constexpr std::byte kBeaconByte{'B'};

std::vector<std::byte> encode_beacon() { return {kBeaconByte}; }

bool is_beacon(std::span<const std::byte> payload) {
  return payload.size() == 1 && payload[0] == kBeaconByte;
}

}  // namespace swarmnet::task_allocation
