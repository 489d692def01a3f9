// The packet trace: one CSV line per packet event, for analysis and for the replay check
// (DESIGN.md section 2: a replay must reproduce the integrated run's trace byte for byte).
//
// Header:  time_ns,event,node,uid,message_id,source,destination,hops,bytes,detail
//   time_ns      simulated time, integer nanoseconds
//   event        send (the application hands a message to routing at its source),
//                forward (routing relays a packet), drop (a layer discards it; detail = reason),
//                deliver (application-level delivery at `node`)
//   node         where it happened
//   uid          packet uid (kept by forwarded copies)
//   message_id   application message id; empty for control packets
//   source       originating node; destination: node id, or -1 for broadcast
//   hops         links traversed so far; bytes: packet size above the MAC (Packet::size_bytes)
//   detail       drop reason (DropReason names), otherwise empty
// Only integers and fixed words are written, so the text is identical on every platform. There
// is no footer line: the run writes the file under a temporary name and renames it when done.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

#include "network/trace_lines.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

enum class PacketEvent : std::uint8_t { send, forward, drop, deliver };

const char* to_string(PacketEvent event);

class PacketTraceWriter {
 public:
  static constexpr std::string_view kHeader =
      "time_ns,event,node,uid,message_id,source,destination,hops,bytes,detail\n";

  // `out` may be null: nothing is written. Otherwise the header line is written first. Lines not
  // yet flushed when the writer goes are discarded (the stream may be gone by then).
  explicit PacketTraceWriter(std::ostream* out) : lines_(out, kHeader) {}

  [[nodiscard]] bool enabled() const { return lines_.enabled(); }

  void record(SimTime time, PacketEvent event, NodeId node, const Packet& packet,
              std::string_view detail = {});

  // Hands buffered lines to the stream (lines are batched in memory between calls).
  void flush() { lines_.flush(); }
  // flush(), then flushes the stream itself.
  void finish() { lines_.finish(); }

 private:
  TraceLines lines_;
};

}  // namespace swarmnet
