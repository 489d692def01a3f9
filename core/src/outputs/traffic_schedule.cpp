#include "outputs/traffic_schedule.hpp"

#include <utility>

namespace swarmnet {

std::ostream& TrafficScheduleWriter::LazyFile::stream() {
  if (out_ == nullptr) {
    out_ = &open_();
    *out_ << header_;
  }
  return *out_;
}

TrafficScheduleWriter::TrafficScheduleWriter(std::ostream& out, std::uint64_t seed, SimTime step,
                                             Open open_send_options, Open open_route_queries,
                                             bool ports)
    : out_(out),
      seed_(seed),
      step_(step),
      ports_(ports),
      send_options_(std::move(open_send_options),
                    ports ? "message_id,hop_limit,report,port\n" : "message_id,hop_limit,report\n"),
      route_queries_(std::move(open_route_queries), "step,robot,destination\n") {
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
    if ((message.hop_limit != 0 || message.report) && send_options_.wanted()) {
      std::ostream& options = send_options_.stream();
      options << message.message_id << ',' << unsigned{message.hop_limit} << ','
              << (message.report ? 1 : 0);
      if (ports_) options << ',' << message.port;
      options << '\n';
    }
  }
  if (batch.route_queries.empty() || !route_queries_.wanted()) return;
  std::ostream& queries = route_queries_.stream();
  for (const RouteQuery& query : batch.route_queries) {
    queries << batch.step << ',' << query.robot << ',' << query.destination << '\n';
  }
}

}  // namespace swarmnet
