#include "network/packet_trace.hpp"

namespace swarmnet {

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

void PacketTraceWriter::record(SimTime time, PacketEvent event, NodeId node, const Packet& packet,
                               std::string_view detail) {
  if (!lines_.enabled()) return;
  lines_.integer(time.count());
  lines_.comma();
  lines_.text(to_string(event));
  lines_.comma();
  lines_.node(node);
  lines_.comma();
  lines_.integer(packet.uid);
  lines_.comma();
  if (!packet.is_control()) lines_.integer(packet.message_id);
  lines_.comma();
  lines_.node(packet.source);
  lines_.comma();
  lines_.node(packet.destination);
  lines_.comma();
  lines_.integer(packet.hops);
  lines_.comma();
  lines_.integer(packet.size_bytes());
  lines_.comma();
  lines_.text(detail);
  lines_.end_line();
}

}  // namespace swarmnet
