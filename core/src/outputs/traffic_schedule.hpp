// Every application message the controllers sent, as CSV, so the same traffic can be replayed:
//   message_id,step,inject_ns,source,destination,payload_bytes
// inject_ns is when the network half takes the message in (step start plus its jitter);
// destination is the robot id, or "broadcast".
#pragma once

#include <ostream>
#include <span>

#include "protocol/step_data.hpp"

namespace swarmnet {

class TrafficScheduleWriter {
 public:
  TrafficScheduleWriter(std::ostream& out, std::uint64_t seed, SimTime step);
  void write(const StepBatch& batch);

 private:
  std::ostream& out_;
  std::uint64_t seed_;
  SimTime step_;
};

}  // namespace swarmnet
