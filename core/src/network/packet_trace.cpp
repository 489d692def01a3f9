#include "network/packet_trace.hpp"

#include <charconv>
#include <type_traits>

namespace swarmnet {

namespace {

constexpr std::size_t kFlushBytes = 1U << 16U;

template <typename Integer>
void append_integer(std::string& out, Integer value) {
  static_assert(std::is_integral_v<Integer>);
  char digits[24];
  const auto result = std::to_chars(std::begin(digits), std::end(digits), value);
  out.append(digits, result.ptr);
}

void append_node(std::string& out, NodeId node) {
  if (node == kBroadcast) {
    out += "-1";
  } else {
    append_integer(out, node);
  }
}

}  // namespace

const char* to_string(PacketEvent event) {
  switch (event) {
    case PacketEvent::send:
      return "send";
    case PacketEvent::forward:
      return "forward";
    case PacketEvent::drop:
      return "drop";
    case PacketEvent::deliver:
      return "deliver";
  }
  return "?";
}

PacketTraceWriter::PacketTraceWriter(std::ostream* out) : out_(out) {
  if (out_ != nullptr) buffer_.append(kHeader);
}

void PacketTraceWriter::record(SimTime time, PacketEvent event, NodeId node, const Packet& packet,
                               std::string_view detail) {
  if (out_ == nullptr) return;
  append_integer(buffer_, time.count());
  buffer_ += ',';
  buffer_ += to_string(event);
  buffer_ += ',';
  append_node(buffer_, node);
  buffer_ += ',';
  append_integer(buffer_, packet.uid);
  buffer_ += ',';
  if (!packet.is_control()) append_integer(buffer_, packet.message_id);
  buffer_ += ',';
  append_node(buffer_, packet.source);
  buffer_ += ',';
  append_node(buffer_, packet.destination);
  buffer_ += ',';
  append_integer(buffer_, packet.hops);
  buffer_ += ',';
  append_integer(buffer_, packet.size_bytes());
  buffer_ += ',';
  buffer_ += detail;
  buffer_ += '\n';
  if (buffer_.size() >= kFlushBytes) flush();
}

void PacketTraceWriter::flush() {
  if (out_ == nullptr || buffer_.empty()) return;
  out_->write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void PacketTraceWriter::finish() {
  flush();
  if (out_ != nullptr) out_->flush();
}

}  // namespace swarmnet
