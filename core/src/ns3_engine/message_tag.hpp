// The robot message a packet carries, as an ns-3 packet tag: the payload is the robot's real
// bytes, so which message it is travels beside them, costing no byte on the air. ns-3 keeps
// packet tags through copies, the IP layer and the channel, so every trace sink and the
// receiving application can tell a message's packets from everything else.
#pragma once

#include <ns3/tag.h>

#include <cstdint>

namespace swarmnet::ns3engine {

class MessageTag final : public ns3::Tag {
 public:
  static ns3::TypeId GetTypeId();

  MessageTag() = default;
  MessageTag(std::uint64_t message_id, std::uint32_t source, std::uint32_t destination)
      : message_id_(message_id), source_(source), destination_(destination) {}

  [[nodiscard]] std::uint64_t message_id() const { return message_id_; }
  [[nodiscard]] std::uint32_t source() const { return source_; }
  // A node id, or kBroadcastNode.
  [[nodiscard]] std::uint32_t destination() const { return destination_; }

  // ns3::Tag
  [[nodiscard]] ns3::TypeId GetInstanceTypeId() const override;
  [[nodiscard]] std::uint32_t GetSerializedSize() const override;
  void Serialize(ns3::TagBuffer buffer) const override;
  void Deserialize(ns3::TagBuffer buffer) override;
  void Print(std::ostream& out) const override;

 private:
  std::uint64_t message_id_ = 0;
  std::uint32_t source_ = 0;
  std::uint32_t destination_ = 0;
};

// True (and `tag` filled) if `packet` carries a robot message.
template <typename PacketPtr>
bool find_message(const PacketPtr& packet, MessageTag& tag) {
  return packet && packet->PeekPacketTag(tag);
}

}  // namespace swarmnet::ns3engine
