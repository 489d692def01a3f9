#include "network/sensing_trace.hpp"

#include <cstddef>
#include <cstdint>

namespace swarmnet {

void SensingTraceWriter::start_row(const StepResult& result, SimTime window_end, RobotId robot,
                                   std::string_view record) {
  lines_.integer(result.step);
  lines_.comma();
  lines_.integer(window_end.count());
  lines_.comma();
  lines_.integer(robot);
  lines_.comma();
  lines_.text(record);
  lines_.comma();
}

void SensingTraceWriter::next_hop(NodeId node) {
  if (node != kNoNode) lines_.node(node);
}

void SensingTraceWriter::record(const StepResult& result, SimTime window_end) {
  if (!lines_.enabled()) return;
  std::size_t entry = 0;
  for (std::size_t robot = 0; robot < result.neighbor_counts.size(); ++robot) {
    for (std::uint32_t i = 0; i < result.neighbor_counts[robot]; ++i, ++entry) {
      const RadioNeighbor& neighbor = result.neighbors[entry];
      start_row(result, window_end, static_cast<RobotId>(robot), "neighbor");
      // peer,time_ns,port,message_id,status,reason,next_hop,hops,attempts,
      lines_.integer(neighbor.id);
      lines_.comma();
      lines_.integer(neighbor.last_heard.count());
      lines_.text(",,,,,,,,");
      // frames,unicasts,first_attempt_acks,rssi_dbm,rssi_smoothed_dbm,sinr_db
      lines_.integer(neighbor.frames);
      lines_.comma();
      lines_.integer(neighbor.unicasts);
      lines_.comma();
      lines_.integer(neighbor.first_attempt_acks);
      lines_.comma();
      lines_.real(neighbor.rssi_dbm);
      lines_.comma();
      lines_.real(neighbor.rssi_smoothed_dbm);
      lines_.comma();
      lines_.real(neighbor.sinr_db);
      lines_.end_line();
    }
  }
  for (const AddressedSendReport& addressed : result.send_reports) {
    const SendReport& report = addressed.report;
    start_row(result, window_end, addressed.source, "report");
    // peer,time_ns,port,message_id,status,reason,next_hop,hops,attempts
    lines_.comma();
    lines_.integer(report.at.count());
    lines_.comma();
    lines_.integer(addressed.port);
    lines_.comma();
    lines_.integer(report.message_id);
    lines_.comma();
    lines_.text(to_string(report.outcome));
    lines_.comma();
    if (report.outcome == SendOutcome::dropped) lines_.text(to_string(report.reason));
    lines_.comma();
    next_hop(report.next_hop);
    lines_.text(",,");
    lines_.integer(report.attempts);
    lines_.text(",,,,,,");
    lines_.end_line();
  }
  for (const RouteAnswer& answer : result.routes) {
    const Route& route = answer.route;
    start_row(result, window_end, answer.query.robot, "route");
    // peer,time_ns,port,message_id,status,reason,next_hop,hops,attempts
    lines_.integer(answer.query.destination);
    lines_.comma();
    lines_.integer(route.as_of.count());
    lines_.text(",,,");
    lines_.text(to_string(route.status));
    lines_.text(",,");
    next_hop(route.next_hop);
    lines_.comma();
    lines_.integer(route.hops);
    lines_.text(",,,,,,,");
    lines_.end_line();
  }
}

}  // namespace swarmnet
