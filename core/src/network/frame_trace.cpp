#include "network/frame_trace.hpp"

namespace swarmnet {

const char* frame_kind(const Frame& frame) {
  switch (frame.type) {
    case FrameType::data:
      return frame.packet && frame.packet->is_arp() ? "arp" : "data";
    case FrameType::ack:
      return "ack";
    case FrameType::rts:
      return "rts";
    case FrameType::cts:
      return "cts";
  }
  return "?";
}

void FrameTraceWriter::record(SimTime time, NodeId node, const Frame& frame) {
  if (!lines_.enabled()) return;
  const bool data = frame.type == FrameType::data;
  lines_.integer(time.count());
  lines_.comma();
  lines_.node(node);
  lines_.comma();
  lines_.text(frame_kind(frame));
  lines_.text(data && frame.retry ? ",1," : ",0,");
  lines_.node(frame.receiver);
  lines_.comma();
  lines_.integer(frame.size_bytes());
  lines_.comma();
  if (data) {
    lines_.integer(frame.sequence);
  } else {
    lines_.text("-1");
  }
  lines_.comma();
  if (data && frame.packet && !frame.packet->is_control()) {
    lines_.integer(frame.packet->message_id);
  } else {
    lines_.text("-1");
  }
  lines_.end_line();
}

}  // namespace swarmnet
