#include "ns3_engine/message_tag.hpp"

#include <ostream>

namespace swarmnet::ns3engine {

ns3::TypeId MessageTag::GetTypeId() {
  // TypeIds live in libns3-core for the life of the process: a second copy of this code (the
  // module loaded again, or beside a test that links the model) finds the name registered and
  // must reuse it, since registering a name twice is fatal in ns-3.
  static const ns3::TypeId tid = [] {
    constexpr const char* kName = "swarmnet::ns3engine::MessageTag";
    ns3::TypeId existing;
    if (ns3::TypeId::LookupByNameFailSafe(kName, &existing)) return existing;
    return ns3::TypeId(kName)
        .SetParent<ns3::Tag>()
        .SetGroupName("SwarmNet")
        .AddConstructor<MessageTag>();
  }();
  return tid;
}

ns3::TypeId MessageTag::GetInstanceTypeId() const { return GetTypeId(); }

std::uint32_t MessageTag::GetSerializedSize() const { return 16; }

void MessageTag::Serialize(ns3::TagBuffer buffer) const {
  buffer.WriteU64(message_id_);
  buffer.WriteU32(source_);
  buffer.WriteU32(destination_);
}

void MessageTag::Deserialize(ns3::TagBuffer buffer) {
  message_id_ = buffer.ReadU64();
  source_ = buffer.ReadU32();
  destination_ = buffer.ReadU32();
}

void MessageTag::Print(std::ostream& out) const {
  out << "message " << message_id_ << " from " << source_ << " to " << destination_;
}

}  // namespace swarmnet::ns3engine
