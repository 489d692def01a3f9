#include "outputs/traffic_schedule.hpp"

#include <utility>

namespace swarmnet {

TrafficScheduleWriter::TrafficScheduleWriter(std::ostream& out, std::uint64_t seed, SimTime step,
                                             std::function<std::ostream&()> open_send_options)
    : out_(out), seed_(seed), step_(step), open_send_options_(std::move(open_send_options)) {
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
    if ((message.hop_limit != 0 || message.report) && open_send_options_) {
      if (send_options_ == nullptr) {
        send_options_ = &open_send_options_();
        *send_options_ << "message_id,hop_limit,report\n";
      }
      *send_options_ << message.message_id << ',' << unsigned{message.hop_limit} << ','
                     << (message.report ? 1 : 0) << '\n';
    }
  }
}

}  // namespace swarmnet
