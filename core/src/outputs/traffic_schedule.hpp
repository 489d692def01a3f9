// Every application message the controllers sent, as CSV, so the same traffic can be replayed:
//   message_id,step,inject_ns,source,destination,payload_bytes
// inject_ns is when the network half takes the message in (step start plus its jitter);
// destination is the robot id, or "broadcast".
//
// Messages sent with options (SendOptions: a hop limit, a report) also get a row in a second
// file, opened only when the first such message is written, so that a run without options writes
// exactly what it always did:
//   message_id,hop_limit,report
// report is 0 or 1.
#pragma once

#include <functional>
#include <ostream>
#include <span>

#include "protocol/step_data.hpp"

namespace swarmnet {

class TrafficScheduleWriter {
 public:
  // `open_send_options` opens the second file; called at most once. Without it, options are not
  // written.
  TrafficScheduleWriter(std::ostream& out, std::uint64_t seed, SimTime step,
                        std::function<std::ostream&()> open_send_options = {});
  void write(const StepBatch& batch);

 private:
  std::ostream& out_;
  std::uint64_t seed_;
  SimTime step_;
  std::function<std::ostream&()> open_send_options_;
  std::ostream* send_options_ = nullptr;
};

}  // namespace swarmnet
