// The frame trace: one CSV line per frame a MAC puts on the air, in the columns of the ns-3
// replay's --frame-trace (tests/validation/ns3_replay_main.cpp), so that the two sides' retry
// sequences, acknowledgements and receivers can be compared frame by frame (docs/validation.md).
//
// Header:  time_ns,node,kind,retry,receiver,bytes,sequence,message_id
//   time_ns      simulated time the transmission starts, integer nanoseconds
//   node         the transmitter
//   kind         data (an IP packet), arp (an ARP request or reply), ack, rts or cts
//   retry        1 if the frame is a retransmission (802.11's Retry bit), else 0
//   receiver     the frame's receiver (a next hop, or the data frame's sender for an ACK), or -1
//                for broadcast
//   bytes        the frame's size on the air, MAC header and FCS included
//   sequence     the data frame's sequence number (the MAC's own counter: dcf80211 counts to
//                65535, where ns-3's 802.11 sequence number wraps at 4096); -1 for other kinds
//   message_id   the application message a data frame carries; -1 for none
// Only integers and fixed words are written. Like packets.csv, the run writes the file under a
// temporary name and renames it when done, so a file that exists is whole.
#pragma once

#include <ostream>
#include <string_view>

#include "network/trace_lines.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class FrameTraceWriter {
 public:
  static constexpr std::string_view kHeader =
      "time_ns,node,kind,retry,receiver,bytes,sequence,message_id\n";

  // `out` may be null: nothing is written. Otherwise the header line is written first. Lines not
  // yet flushed when the writer goes are discarded (the stream may be gone by then).
  explicit FrameTraceWriter(std::ostream* out) : lines_(out, kHeader) {}

  [[nodiscard]] bool enabled() const { return lines_.enabled(); }

  // `frame` as `node` puts it on the air at `time` (the channel fills in frame.transmitter later).
  void record(SimTime time, NodeId node, const Frame& frame);

  // Hands buffered lines to the stream (lines are batched in memory between calls).
  void flush() { lines_.flush(); }
  // flush(), then flushes the stream itself.
  void finish() { lines_.finish(); }

 private:
  TraceLines lines_;
};

// The trace's name for what `frame` is: data, arp, ack, rts or cts.
const char* frame_kind(const Frame& frame);

}  // namespace swarmnet
