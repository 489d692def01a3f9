#include "network/sensing_trace.hpp"

#include <cstddef>
#include <cstdint>

namespace swarmnet {

void SensingTraceWriter::start_row(const StepResult& result, SimTime window_end, RobotId robot,
                                   std::string_view record) {
  integers(result.step, window_end.count(), robot);
  lines_.text(record);
  lines_.comma();
}

void SensingTraceWriter::next_hop(NodeId node) {
  if (node != kNoNode) lines_.node(node);
  lines_.comma();
}

void SensingTraceWriter::record(const StepResult& result, SimTime window_end) {
  if (!lines_.enabled()) return;
  // Each row: start_row's four columns, then peer,time_ns,port,message_id,status,reason,next_hop,
  // hops,attempts,frames,unicasts,first_attempt_acks,rssi_dbm,rssi_smoothed_dbm,sinr_db.
  std::size_t entry = 0;
  for (std::size_t robot = 0; robot < result.neighbor_counts.size(); ++robot) {
    for (std::uint32_t i = 0; i < result.neighbor_counts[robot]; ++i, ++entry) {
      const RadioNeighbor& neighbor = result.neighbors[entry];
      start_row(result, window_end, static_cast<RobotId>(robot), "neighbor");
      integers(neighbor.id, neighbor.last_heard.count());
      lines_.text(",,,,,,,");  // port to attempts
      integers(neighbor.frames, neighbor.unicasts, neighbor.first_attempt_acks);
      for (const double real : {neighbor.rssi_dbm, neighbor.rssi_smoothed_dbm}) {
        lines_.real(real);
        lines_.comma();
      }
      lines_.real(neighbor.sinr_db);
      lines_.end_line();
    }
  }
  for (const AddressedSendReport& addressed : result.send_reports) {
    const SendReport& report = addressed.report;
    start_row(result, window_end, addressed.source, "report");
    lines_.comma();  // peer
    integers(report.at.count(), addressed.port, report.message_id);
    lines_.text(to_string(report.outcome));
    lines_.comma();
    if (report.outcome == SendOutcome::dropped) lines_.text(to_string(report.reason));
    lines_.comma();
    next_hop(report.next_hop);
    lines_.comma();  // hops
    lines_.integer(report.attempts);
    lines_.text(",,,,,,");  // frames to sinr_db
    lines_.end_line();
  }
  for (const RouteAnswer& answer : result.routes) {
    const Route& route = answer.route;
    start_row(result, window_end, answer.query.robot, "route");
    integers(answer.query.destination, route.as_of.count());
    lines_.text(",,");  // port, message_id
    lines_.text(to_string(route.status));
    lines_.text(",,");  // reason
    next_hop(route.next_hop);
    lines_.integer(route.hops);
    lines_.text(",,,,,,,");  // attempts to sinr_db
    lines_.end_line();
  }
}

}  // namespace swarmnet
