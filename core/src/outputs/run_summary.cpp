#include "outputs/run_summary.hpp"

#include "outputs/output_files.hpp"

namespace swarmnet {

namespace {

using Json = nlohmann::ordered_json;

Json counts_json(const std::vector<NamedCount>& counts) {
  Json out = Json::object();
  for (const NamedCount& c : counts) out[c.name] = c.value;
  return out;
}

Json optional_json(const std::optional<double>& value) {
  return value ? Json(*value) : Json(nullptr);
}

Json controllers_json(const ControllerMetrics& metrics) {
  Json out = Json::object();
  for (const auto& [name, stats] : metrics) {
    out[name] = {{"count", stats.count},
                 {"sum", stats.sum},
                 {"mean", stats.mean()},
                 {"min", stats.count > 0 ? Json(stats.min) : Json(nullptr)},
                 {"max", stats.count > 0 ? Json(stats.max) : Json(nullptr)}};
  }
  return out;
}

Json outputs_json(const Scenario& scenario, bool replay) {
  if (replay) {
    Json outputs = {{"summary", kSummaryFile}, {"packet_trace", kPacketTraceFile}};
    if (scenario.output.frame_trace) outputs["frame_trace"] = kFrameTraceFile;
    if (scenario.output.sensing_trace) outputs["sensing_trace"] = kSensingTraceFile;
    return outputs;
  }
  Json outputs = {
      {"summary", kSummaryFile}, {"scenario", kResolvedScenarioFile}, {"log", kLogFile}};
  if (scenario.output.packet_trace) outputs["packet_trace"] = kPacketTraceFile;
  if (scenario.output.frame_trace) outputs["frame_trace"] = kFrameTraceFile;
  if (scenario.output.sensing_trace) outputs["sensing_trace"] = kSensingTraceFile;
  if (scenario.output.mobility_trace) {
    outputs["mobility_trace"] = kMobilityTraceFile;
    outputs["positions"] = kPositionsTraceFile;
  }
  if (scenario.output.traffic_schedule) outputs["traffic_schedule"] = kTrafficScheduleFile;
  return outputs;
}

}  // namespace

Json network_report_json(const NetworkReport& report) {
  Json summary;
  Json packets;
  packets["sent"] = report.sent;
  packets["delivered"] = report.delivered;
  packets["dropped"] = counts_json(report.dropped);
  packets["broadcast_sent"] = report.broadcast_sent;
  packets["broadcast_deliveries"] = report.broadcast_deliveries;
  packets["undelivered"] = report.undelivered;
  packets["duplicates"] = report.duplicates;
  summary["packets"] = packets;
  summary["pdr"] = report.pdr;
  summary["delay_s"] = {{"mean", optional_json(report.delay_mean_s)},
                        {"p50", optional_json(report.delay_p50_s)},
                        {"p95", optional_json(report.delay_p95_s)}};
  summary["hops_mean"] = optional_json(report.hops_mean);
  summary["mac"] = counts_json(report.mac);
  summary["routing"] = counts_json(report.routing);
  summary["arp"] = counts_json(report.arp);
  summary["events"] = report.events;
  return summary;
}

Json build_summary(const SummaryInputs& in) {
  const Scenario& scenario = *in.scenario;
  const std::uint64_t steps = in.steps.value_or(scenario.step_count());
  const double sim_s = static_cast<double>(steps) * scenario.step_s;
  const RunTimings& t = in.timings;
  Json s;
  s["scenario"] = scenario.name;
  if (in.replay_of) {
    s["replay_of"] = {{"scenario", in.replay_of->scenario.string()},
                      {"positions", in.replay_of->positions.string()},
                      {"traffic", in.replay_of->traffic.string()}};
  } else {
    s["scenario_file"] = scenario.source.string();
  }
  s["seed"] = scenario.seed;
  s["robots"] = scenario.robots.count;
  s["duration_s"] = scenario.duration_s;  // the cap, when a world ends the run earlier
  s["sim_time_s"] = sim_s;
  s["step_s"] = scenario.step_s;
  s["steps"] = steps;
  if (in.ended) {
    s["ended"] = {{"by", in.ended->by_world ? "task_done" : "duration"},
                  {"world", in.ended->by_world ? Json(*in.ended->by_world) : Json(nullptr)},
                  {"at_s", sim_s}};
  }
  if (!in.replay_of) s["sync"] = to_string(scenario.sync);
  if (in.transport) s["transport"] = *in.transport;
  s["engine"] = to_string(scenario.network.engine);
  s["wall_s"] = t.wall_s;
  if (t.robot_cpu_s && t.transport_cpu_s) {
    s["cpu_s"] = {{"robot", *t.robot_cpu_s},
                  {"network", t.network_cpu_s},
                  {"transport", *t.transport_cpu_s},
                  {"total", *t.robot_cpu_s + t.network_cpu_s + *t.transport_cpu_s}};
  } else {
    s["cpu_s"] = {{"network", t.network_cpu_s}};
  }
  s["realtime_factor"] = t.wall_s > 0 ? sim_s / t.wall_s : 0.0;
  // CPU both halves spent encoding, moving and waiting on records, as a share of the run.
  if (t.transport_cpu_s) s["transport_share"] = t.wall_s > 0 ? *t.transport_cpu_s / t.wall_s : 0.0;
  s.update(network_report_json(*in.network));
  if (in.controllers != nullptr) s["controllers"] = controllers_json(*in.controllers);
  if (in.world != nullptr) s["world"] = controllers_json(*in.world);
  s["outputs"] = outputs_json(scenario, in.replay_of.has_value());
  return s;
}

}  // namespace swarmnet
