#include "frame_format.hpp"

#include <utility>

namespace swarmnet::dcf80211 {

Frame make_data(Packet packet, NodeId receiver, std::uint32_t header_bytes, std::uint16_t sequence,
                bool retry, const DcfTiming& timing) {
  Frame frame;
  frame.type = FrameType::data;
  frame.receiver = receiver;
  frame.header_bytes = header_bytes;
  frame.bitrate_bps = timing.data_mode.rate_bps;
  frame.sequence = sequence;
  frame.retry = retry;
  frame.nav = timing.data_nav(receiver != kBroadcast);
  frame.packet = std::move(packet);
  return frame;
}

namespace {

Frame control_frame(FrameType type, NodeId receiver, std::uint32_t bytes, SimTime nav,
                    const DcfTiming& timing) {
  Frame frame;
  frame.type = type;
  frame.receiver = receiver;
  frame.header_bytes = bytes;
  frame.bitrate_bps = timing.control_mode.rate_bps;
  frame.nav = nav;
  return frame;
}

}  // namespace

Frame make_ack(NodeId receiver, const DcfTiming& timing) {
  return control_frame(FrameType::ack, receiver, kAckBytes, kTimeZero, timing);
}

Frame make_rts(NodeId receiver, std::uint32_t data_mpdu_bytes, const DcfTiming& timing) {
  return control_frame(FrameType::rts, receiver, kRtsBytes, timing.rts_nav(data_mpdu_bytes),
                       timing);
}

Frame make_cts(const Frame& rts, const DcfTiming& timing) {
  return control_frame(FrameType::cts, rts.transmitter, kCtsBytes, timing.cts_nav(rts.nav), timing);
}

SimTime airtime(const Frame& frame, const DcfTiming& timing) {
  const ofdm::Mode mode = frame.type == FrameType::data ? timing.data_mode : timing.control_mode;
  return ofdm::frame_duration(frame.size_bytes(), mode);
}

}  // namespace swarmnet::dcf80211
