#include "outputs/traffic_schedule.hpp"

namespace swarmnet {

TrafficScheduleWriter::TrafficScheduleWriter(std::ostream& out, std::uint64_t seed, SimTime step)
    : out_(out), seed_(seed), step_(step) {
  out_ << "message_id,step,inject_ns,source,destination,payload_bytes\n";
}

void TrafficScheduleWriter::write(const StepBatch& batch) {
  for (const AppMessage& message : batch.messages) {
    const SimTime inject = batch.start + injection_offset(seed_, message.message_id, step_);
    out_ << message.message_id << ',' << batch.step << ',' << inject.count() << ','
         << message.source << ',';
    if (message.destination == kBroadcast) {
      out_ << "broadcast";
    } else {
      out_ << message.destination;
    }
    out_ << ',' << message.payload.size() << '\n';
  }
}

}  // namespace swarmnet
