#include "session/replay.hpp"

#include <chrono>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "coupling/cpu_clock.hpp"
#include "coupling/network_engine_choice.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/output_files.hpp"
#include "outputs/positions_trace.hpp"
#include "outputs/run_error.hpp"
#include "outputs/run_summary.hpp"
#include "outputs/text_file.hpp"
#include "plugin/plugin_loader.hpp"
#include "protocol/step_data.hpp"
#include "scenario/scenario_loader.hpp"

namespace swarmnet {

namespace {

struct TrafficRow {
  std::uint64_t step = 0;
  std::int64_t inject_ns = 0;
  AppMessage message;
};

std::uint64_t parse_unsigned(const std::string& field, const std::string& where) {
  std::size_t used = 0;
  std::uint64_t value = 0;
  try {
    value = std::stoull(field, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != field.size() || field.front() == '-') {
    throw RunError(where + ": '" + field + "' is not a non-negative integer");
  }
  return value;
}

// Calls `row(fields, where)` for each non-empty line of the CSV file `path` after its header,
// which must be `header`; every line must have `field_count` fields. `what` names the file kind
// in the refusal of another header; `where` is "path:line".
template <typename Row>
void read_csv(const std::filesystem::path& path, const char* header, const char* what,
              std::size_t field_count, Row row) {
  std::ifstream in(path);
  if (!in) throw RunError("cannot open " + path.string());
  std::string line;
  std::getline(in, line);
  if (line != header) {
    throw RunError(path.string() + ":1: not a SwarmNet " + what + " (unexpected header)");
  }
  std::size_t number = 1;
  std::vector<std::string> fields;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const std::string where = path.string() + ":" + std::to_string(number);
    fields.clear();
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    if (fields.size() != field_count) {
      throw RunError(where + ": expected " + std::to_string(field_count) + " fields");
    }
    row(fields, where);
  }
}

// traffic.csv (run/traffic_schedule.hpp), in file order (= send order within each step).
std::vector<TrafficRow> read_traffic(const std::filesystem::path& path) {
  std::vector<TrafficRow> rows;
  read_csv(path, "message_id,step,inject_ns,source,destination,payload_bytes", "traffic schedule",
           6, [&](const std::vector<std::string>& fields, const std::string& where) {
             TrafficRow row;
             row.message.message_id = parse_unsigned(fields[0], where);
             row.step = parse_unsigned(fields[1], where);
             row.inject_ns = static_cast<std::int64_t>(parse_unsigned(fields[2], where));
             row.message.source = static_cast<RobotId>(parse_unsigned(fields[3], where));
             row.message.destination = fields[4] == "broadcast"
                                           ? kBroadcast
                                           : static_cast<RobotId>(parse_unsigned(fields[4], where));
             const std::uint64_t bytes = parse_unsigned(fields[5], where);
             if (bytes > kMaxPayloadBytes)
               throw RunError(where + ": payload larger than the maximum");
             row.message.payload.assign(bytes, std::byte{0});
             if (!rows.empty() && row.step < rows.back().step) {
               throw RunError(where + ": steps are not in ascending order");
             }
             rows.push_back(std::move(row));
           });
  return rows;
}

// The first line of `path`, without its line break; empty when it cannot be read.
std::string first_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// send_options.csv (outputs/traffic_schedule.hpp) beside `traffic`, applied to the messages it
// names; absent when no message of the run had options. A run with a sensing trace adds the
// sending controller's port, which its send reports name; without it, replayed messages have
// port 0 (nothing else the network half writes shows a port).
void apply_send_options(const std::filesystem::path& traffic, std::vector<TrafficRow>& rows) {
  const std::filesystem::path path = traffic.parent_path() / kSendOptionsFile;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return;
  std::map<std::uint64_t, TrafficRow*> by_id;
  for (TrafficRow& row : rows) by_id[row.message.message_id] = &row;
  constexpr const char* kWithPorts = "message_id,hop_limit,report,port";
  const bool ports = first_line(path) == kWithPorts;
  read_csv(path, ports ? kWithPorts : "message_id,hop_limit,report", "send options file",
           ports ? 4 : 3, [&](const std::vector<std::string>& fields, const std::string& where) {
             const std::uint64_t id = parse_unsigned(fields[0], where);
             const std::uint64_t hop_limit = parse_unsigned(fields[1], where);
             const std::uint64_t report = parse_unsigned(fields[2], where);
             if (hop_limit > 255 || report > 1) {
               throw RunError(where + ": hop_limit is 0 to 255 and report 0 or 1");
             }
             const std::uint64_t port = ports ? parse_unsigned(fields[3], where) : 0;
             if (port > 65535) throw RunError(where + ": port is 0 to 65535");
             const auto row = by_id.find(id);
             if (row == by_id.end()) {
               throw RunError(where + ": message " + std::to_string(id) + " is not in " +
                              traffic.string());
             }
             row->second->message.hop_limit = static_cast<std::uint8_t>(hop_limit);
             row->second->message.report = report == 1;
             row->second->message.port = static_cast<std::uint16_t>(port);
           });
}

struct RouteQueryRow {
  std::uint64_t step = 0;
  RouteQuery query;
};

// route_queries.csv (outputs/traffic_schedule.hpp) beside `traffic`, in file order: each step's
// queries as the run's batch held them. Empty when absent (no controller of the run asked).
// Refuses, naming the line, what no run writes: a robot that is not one of the scenario's
// `robots`, a robot asking about itself, steps out of order, a step's queries not ascending by
// (robot, destination), or more than kMaxRouteQueriesPerRobot of one robot in a step.
std::vector<RouteQueryRow> read_route_queries(const std::filesystem::path& traffic,
                                              std::uint32_t robots) {
  const std::filesystem::path path = traffic.parent_path() / kRouteQueriesFile;
  std::vector<RouteQueryRow> rows;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return rows;
  std::uint32_t asked_by_robot = 0;  // queries of rows.back()'s robot in its step
  read_csv(path, "step,robot,destination", "route queries file", 3,
           [&](const std::vector<std::string>& fields, const std::string& where) {
             RouteQueryRow row;
             row.step = parse_unsigned(fields[0], where);
             const std::uint64_t robot = parse_unsigned(fields[1], where);
             const std::uint64_t destination = parse_unsigned(fields[2], where);
             if (robot >= robots || destination >= robots || robot == destination) {
               throw RunError(where + ": robot " + fields[1] + " asking about " + fields[2] +
                              " is not a robot asking about another of the scenario's " +
                              std::to_string(robots));
             }
             row.query = RouteQuery{static_cast<RobotId>(robot), static_cast<RobotId>(destination)};
             if (!rows.empty() && row.step < rows.back().step) {
               throw RunError(where + ": steps are not in ascending order");
             }
             const bool same_step = !rows.empty() && row.step == rows.back().step;
             if (same_step && !(rows.back().query < row.query)) {
               throw RunError(where +
                              ": a step's queries are not ascending by robot, then "
                              "destination, without repeats");
             }
             asked_by_robot =
                 same_step && rows.back().query.robot == row.query.robot ? asked_by_robot + 1 : 1;
             if (asked_by_robot > kMaxRouteQueriesPerRobot) {
               throw RunError(where + ": robot " + fields[1] + " asks more than " +
                              std::to_string(kMaxRouteQueriesPerRobot) + " routes in step " +
                              fields[0]);
             }
             rows.push_back(row);
           });
  return rows;
}

}  // namespace

ReplayInputs ReplayInputs::from_run_dir(const std::filesystem::path& run_dir) {
  return {run_dir / kResolvedScenarioFile, run_dir / kPositionsTraceFile,
          run_dir / kTrafficScheduleFile};
}

ReplayOutcome replay_network(const ReplayInputs& inputs, const std::filesystem::path& out_dir) {
  const auto wall_start = std::chrono::steady_clock::now();
  PluginLoader loader;
  const Scenario scenario =
      load_scenario_text(read_text_file(inputs.scenario), inputs.scenario.string(), loader);
  const PositionsTrace positions = read_positions_trace(inputs.positions);
  std::vector<TrafficRow> traffic = read_traffic(inputs.traffic);
  apply_send_options(inputs.traffic, traffic);
  const std::vector<RouteQueryRow> route_queries =
      read_route_queries(inputs.traffic, scenario.robots.count);
  const SimTime step = from_seconds(scenario.step_s);
  // Fewer steps than the scenario's only when a world plugin may have ended the run early.
  const bool may_end_early = !scenario.worlds.empty();
  if (positions.robots != scenario.robots.count || positions.step != step ||
      positions.steps > scenario.step_count() ||
      (!may_end_early && positions.steps != scenario.step_count())) {
    throw RunError(inputs.positions.string() + " (" + std::to_string(positions.robots) +
                   " robots, " + std::to_string(positions.steps) + " steps of " +
                   std::to_string(positions.step.count()) + " ns) does not match " +
                   inputs.scenario.string());
  }

  ReplayOutcome outcome;
  outcome.dir = out_dir;
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw RunError("cannot create " + out_dir.string() + ": " + ec.message());
  std::filesystem::remove(out_dir / kSummaryFile, ec);

  const double cpu_start = thread_cpu_seconds();
  std::optional<AtomicFile> trace;
  std::optional<AtomicFile> frames;
  std::optional<AtomicFile> sensing;
  if (scenario.network.engine == NetworkEngineKind::native) {
    trace.emplace(out_dir / kPacketTraceFile);
    if (scenario.output.frame_trace) frames.emplace(out_dir / kFrameTraceFile);
    if (scenario.output.sensing_trace) sensing.emplace(out_dir / kSensingTraceFile);
  }
  const NetworkTraceStreams traces{trace ? &trace->stream() : nullptr,
                                   frames ? &frames->stream() : nullptr,
                                   sensing ? &sensing->stream() : nullptr};
  const std::unique_ptr<NetworkEngine> engine = make_network_engine(scenario, loader, traces);
  NetworkEngine& simulator = *engine;
  StepBatch batch;
  StepResult result;
  std::size_t next = 0;
  std::size_t next_query = 0;
  for (std::uint64_t i = 0; i < positions.steps; ++i) {
    batch.step = i;
    batch.start = step * static_cast<std::int64_t>(i);
    const auto at = positions.at_step(i);
    batch.positions.assign(at.begin(), at.end());
    batch.messages.clear();
    for (; next < traffic.size() && traffic[next].step == i; ++next) {
      const TrafficRow& row = traffic[next];
      // The recorded injection time checks that seed and step length are the run's.
      const SimTime inject =
          batch.start + injection_offset(scenario.seed, row.message.message_id, step);
      if (inject.count() != row.inject_ns) {
        throw RunError(inputs.traffic.string() + ": message " +
                       std::to_string(row.message.message_id) +
                       " was injected at a time this scenario would not give it (another seed "
                       "or step length?)");
      }
      batch.messages.push_back(row.message);
    }
    batch.route_queries.clear();
    for (; next_query < route_queries.size() && route_queries[next_query].step == i; ++next_query) {
      batch.route_queries.push_back(route_queries[next_query].query);
    }
    simulator.run_step(batch, result);
  }
  if (next != traffic.size()) {
    throw RunError(inputs.traffic.string() + ": messages after the last step (" +
                   std::to_string(traffic[next].step) + ")");
  }
  if (next_query != route_queries.size()) {
    throw RunError((inputs.traffic.parent_path() / kRouteQueriesFile).string() +
                   ": route queries after the last step (" +
                   std::to_string(route_queries[next_query].step) + ")");
  }
  simulator.finish();
  const double network_cpu = thread_cpu_seconds() - cpu_start;
  for (std::optional<AtomicFile>* file : {&trace, &frames, &sensing}) {
    if (*file) (*file)->commit();
  }

  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const NetworkReport report = simulator.report();
  SummaryInputs summary;
  summary.scenario = &scenario;
  summary.replay_of = SummaryInputs::ReplayOf{inputs.scenario, inputs.positions, inputs.traffic};
  summary.timings.wall_s = wall_s;
  summary.timings.network_cpu_s = network_cpu;
  summary.network = &report;
  summary.steps = positions.steps;
  outcome.summary = build_summary(summary);
  write_file_atomically(out_dir / kSummaryFile, outcome.summary.dump(2) + "\n");
  return outcome;
}

}  // namespace swarmnet
