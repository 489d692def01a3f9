// The sensing trace (output.sensing_trace, sensing.csv): what the network half handed the robot
// half at the end of each step's window for its controllers to sense, so that a run's neighbour
// tables, send reports and route answers can be read afterwards and compared with a replay's.
// One row per record, in the order the StepResult carries them: the window's neighbour tables
// (robot by robot, each ascending by neighbour id), then its send reports (in the order their
// outcomes happened), then its route answers (in the order of the batch's queries).
//
// Header:  step,window_end_ns,robot,record,peer,time_ns,port,message_id,status,reason,next_hop,
//          hops,attempts,frames,unicasts,first_attempt_acks,rssi_dbm,rssi_smoothed_dbm,sinr_db
//   step           the window's step index; window_end_ns: its end, integer nanoseconds
//   robot          whose record it is: the table's robot, the message's source, the robot that
//   asked record         neighbor, report or route; each fills its own columns and leaves the
//   others
//                  empty:
//   neighbor       peer (the node heard), time_ns (last_heard), frames, unicasts,
//                  first_attempt_acks, rssi_dbm, rssi_smoothed_dbm, sinr_db (RadioNeighbor)
//   report         port (the sending controller's), message_id, status (the SendOutcome:
//                  acknowledged, sent or dropped), reason (a DropReason, for dropped only),
//                  time_ns (when the outcome happened), next_hop, attempts (SendReport)
//   route          peer (the destination asked about), status (a RouteStatus: not_tracked, none
//                  or valid), next_hop, hops, time_ns (as_of) (RouteAnswer)
// next_hop is a node id, -1 for broadcast, empty for none. Integers are exact; reals are the
// shortest decimal that reads back as the same double (inf for the threshold PHY's sinr_db).
// Every window that was simulated has its rows, also the last ones that no robot step read.
// Written by the network simulator itself, so a run and `swarmnet replay` of it write it alike;
// like packets.csv, under a temporary name renamed when the run is done.
#pragma once

#include <ostream>
#include <string_view>

#include "network/trace_lines.hpp"
#include "protocol/step_data.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class SensingTraceWriter {
 public:
  static constexpr std::string_view kHeader =
      "step,window_end_ns,robot,record,peer,time_ns,port,message_id,status,reason,next_hop,hops,"
      "attempts,frames,unicasts,first_attempt_acks,rssi_dbm,rssi_smoothed_dbm,sinr_db\n";

  // `out` may be null: nothing is written. Otherwise the header line is written first. Lines not
  // yet flushed when the writer goes are discarded (the stream may be gone by then).
  explicit SensingTraceWriter(std::ostream* out) : lines_(out, kHeader) {}

  [[nodiscard]] bool enabled() const { return lines_.enabled(); }

  // The rows of `result`, the window of step result.step that ended at `window_end`.
  void record(const StepResult& result, SimTime window_end);

  // Hands buffered lines to the stream (lines are batched in memory between calls).
  void flush() { lines_.flush(); }
  // flush(), then flushes the stream itself.
  void finish() { lines_.finish(); }

 private:
  // step,window_end_ns,robot,record, of a row.
  void start_row(const StepResult& result, SimTime window_end, RobotId robot,
                 std::string_view record);
  // A node id (-1 for broadcast), or nothing for kNoNode; then a comma.
  void next_hop(NodeId node);
  // Each value, in decimal, followed by a comma.
  template <typename... Integers>
  void integers(Integers... values) {
    ((lines_.integer(values), lines_.comma()), ...);
  }

  TraceLines lines_;
};

}  // namespace swarmnet
