// The frame trace's lines (output.frame_trace, frames.csv): the replay's --frame-trace columns,
// one line per frame, every kind of frame.
#include "network/frame_trace.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace swarmnet {
namespace {

Frame data_frame(NodeId to, std::uint16_t sequence, bool retry) {
  Frame frame;
  frame.type = FrameType::data;
  frame.receiver = to;
  frame.header_bytes = 36;
  frame.sequence = sequence;
  frame.retry = retry;
  Packet packet;
  packet.message_id = 42;
  packet.payload = std::make_shared<const Payload>(100);
  frame.packet = packet;
  return frame;
}

TEST(FrameTrace, WritesTheHeaderThenOneLinePerFrame) {
  std::ostringstream out;
  FrameTraceWriter writer(&out);
  EXPECT_TRUE(writer.enabled());
  writer.record(SimTime{1000}, 3, data_frame(7, 4095, false));
  writer.record(SimTime{2000}, 3, data_frame(7, 4095, true));
  Frame ack;
  ack.type = FrameType::ack;
  ack.receiver = 3;
  ack.header_bytes = 14;
  ack.retry = true;  // an ACK's trace line carries no Retry bit, whatever the struct holds
  writer.record(SimTime{2300}, 7, ack);
  Frame request = data_frame(kBroadcast, 12, false);
  request.packet->protocol = LinkProtocol::arp_request;
  request.packet->message_id = kNoMessage;
  request.packet->payload.reset();
  writer.record(SimTime{3000}, 5, request);
  Frame control = data_frame(6, 13, false);  // a routing protocol's control packet
  control.packet->message_id = kNoMessage;
  control.packet->header.assign(24, 0);
  control.packet->payload.reset();
  writer.record(SimTime{3500}, 5, control);
  Frame rts;
  rts.type = FrameType::rts;
  rts.receiver = 2;
  rts.header_bytes = 20;
  writer.record(SimTime{4000}, 1, rts);
  Frame cts = rts;
  cts.type = FrameType::cts;
  cts.receiver = 1;
  cts.header_bytes = 14;
  writer.record(SimTime{4100}, 2, cts);
  writer.finish();
  EXPECT_EQ(out.str(),
            "time_ns,node,kind,retry,receiver,bytes,sequence,message_id\n"
            "1000,3,data,0,7,164,4095,42\n"
            "2000,3,data,1,7,164,4095,42\n"
            "2300,7,ack,0,3,14,-1,-1\n"
            "3000,5,arp,0,-1,64,12,-1\n"
            "3500,5,data,0,6,88,13,-1\n"
            "4000,1,rts,0,2,20,-1,-1\n"
            "4100,2,cts,0,1,14,-1,-1\n");
}

TEST(FrameTrace, WithoutAStreamWritesNothing) {
  FrameTraceWriter writer(nullptr);
  EXPECT_FALSE(writer.enabled());
  writer.record(SimTime{1}, 0, data_frame(1, 0, false));
  writer.finish();  // must not touch a stream
}

}  // namespace
}  // namespace swarmnet
