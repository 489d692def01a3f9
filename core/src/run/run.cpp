#include "run/run.hpp"

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cinttypes>
#include <csignal>
#include <optional>
#include <sstream>
#include <thread>

#include "plugin/plugin_loader.hpp"
#include "robot/robot_world.hpp"
#include "run/atomic_file.hpp"
#include "run/cpu_clock.hpp"
#include "run/mobility_trace.hpp"
#include "run/network_link.hpp"
#include "run/output_files.hpp"
#include "run/positions_trace.hpp"
#include "run/progress_line.hpp"
#include "run/run_error.hpp"
#include "run/stop_signal.hpp"
#include "run/traffic_schedule.hpp"
#include "shm_segment.hpp"
#include "step_channel.hpp"

namespace swarmnet {

namespace {

const char* to_string(SyncMode mode) { return mode == SyncMode::strict ? "strict" : "pipelined"; }

// The channel to the network half failed; distinct from a failure of the robot half itself.
class PeerLost : public RunError {
 public:
  using RunError::RunError;
};

// How many steps later the robot half reads a window's deliveries (DESIGN.md section 2).
std::uint64_t delivery_lag(SyncMode mode) { return mode == SyncMode::strict ? 1 : 2; }

std::string to_yaml(const YAML::Node& node) {
  YAML::Emitter emitter;
  emitter << node;
  return std::string(emitter.c_str()) + "\n";
}

// run.log: what was run with which plugins, and how it ended.
class RunLog {
 public:
  explicit RunLog(const std::filesystem::path& path) : file_(path) {}
  void line(const std::string& text) { file_.stream() << text << '\n'; }
  void commit() { file_.commit(); }

 private:
  AtomicFile file_;
};

void log_plugins(RunLog& log, const Scenario& scenario, PluginLoader& loader) {
  auto describe = [&](const PluginChoice& choice) {
    const auto library = loader.find(choice.name, choice.kind);
    std::ostringstream text;
    text << "  " << to_string(choice.kind) << " " << choice.name << " " << library->info().version
         << " (" << library->path().string() << ")";
    log.line(text.str());
  };
  log.line("plugins:");
  describe(scenario.physics);
  for (const auto& controller : scenario.robots.controllers) describe(controller);
  for (const auto& model : scenario.network.propagation) describe(model);
  describe(scenario.network.mac);
  describe(scenario.network.routing);
}

nlohmann::ordered_json controller_metrics_json(const RobotWorld& world) {
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  for (const auto& [name, stats] : world.controller_metrics()) {
    metrics[name] = {{"count", stats.count},
                     {"sum", stats.sum},
                     {"mean", stats.count > 0 ? stats.sum / static_cast<double>(stats.count) : 0.0},
                     {"min", stats.count > 0 ? nlohmann::ordered_json(stats.min) : nullptr},
                     {"max", stats.count > 0 ? nlohmann::ordered_json(stats.max) : nullptr}};
  }
  return metrics;
}

// Removes files that other processes left under a temporary name (AtomicFile's ".partial-PID")
// in `dir`; this process's own (the log being written) stay.
void remove_partial_files(const std::filesystem::path& dir) {
  const std::string own = ".partial-" + std::to_string(::getpid());
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".partial-") != std::string::npos && !name.ends_with(own)) {
      std::filesystem::remove(entry.path(), ec);
    }
  }
}

void handshake(const Scenario& scenario, const std::filesystem::path& run_dir,
               StepChannel& channel) {
  Hello hello;
  hello.seed = scenario.seed;
  hello.robots = scenario.robots.count;
  hello.step_ns = from_seconds(scenario.step_s).count();
  hello.scenario_yaml = to_yaml(scenario.resolved);
  hello.run_dir = std::filesystem::absolute(run_dir).string();
  if (const ProtocolResult r = channel.send_hello(hello); !r.ok()) throw PeerLost(r.error);
  if (const ProtocolResult r = channel.receive_welcome(hello); !r.ok()) throw PeerLost(r.error);
}

// Drives the robot half over `channel` for every step; returns the network half's report.
struct RobotLoopCost {
  double transport_cpu_s = 0.0;
};

std::string drive_robot_half(const Scenario& scenario, RobotWorld& world, StepChannel& channel,
                             MobilityTraceWriter* mobility, PositionsTraceWriter* positions,
                             TrafficScheduleWriter* traffic, ProgressLine& progress,
                             RobotLoopCost& cost) {
  const std::uint64_t steps = scenario.step_count();
  const std::uint64_t lag = delivery_lag(scenario.sync);
  StepBatch batch;
  StepResult result;
  std::vector<Delivery> no_deliveries;

  auto receive = [&](std::uint64_t expected_step) {
    const double before = thread_cpu_seconds();
    const ProtocolResult received = channel.receive_result(result);
    cost.transport_cpu_s += thread_cpu_seconds() - before;
    if (!received.ok()) throw PeerLost(received.error);
    if (result.step != expected_step) {
      throw PeerLost("protocol error: the network half answered step " +
                     std::to_string(result.step) + " where step " + std::to_string(expected_step) +
                     " was due");
    }
  };

  for (std::uint64_t step = 0; step < steps; ++step) {
    if (stop_signal() != 0) throw RunError("interrupted");
    const std::vector<Delivery>* deliveries = &no_deliveries;
    if (step >= lag) {
      receive(step - lag);
      deliveries = &result.deliveries;
    }
    batch.step = step;
    batch.start = world.now();
    const auto bodies = world.bodies();
    batch.positions.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) batch.positions[i] = bodies[i].position;
    if (mobility != nullptr) mobility->sample(step, batch.positions);
    if (positions != nullptr) positions->sample(batch.positions);

    batch.messages.clear();
    world.step(*deliveries, batch.messages);
    if (traffic != nullptr) traffic->write(batch);

    const double before = thread_cpu_seconds();
    const ProtocolResult sent = channel.send_batch(batch);
    cost.transport_cpu_s += thread_cpu_seconds() - before;
    if (!sent.ok()) throw PeerLost(sent.error);
    progress.update(step + 1);
  }
  // Windows whose deliveries no robot step will read any more: still simulated and counted.
  for (std::uint64_t step = steps > lag ? steps - lag : 0; step < steps; ++step) receive(step);
  if (const ProtocolResult r = channel.send_finish(); !r.ok()) throw PeerLost(r.error);
  std::string report;
  if (const ProtocolResult r = channel.receive_report(report); !r.ok()) throw PeerLost(r.error);
  return report;
}

}  // namespace

RunOutcome run_scenario(const Scenario& scenario, const RunOptions& options) {
  RunOutcome outcome;
  outcome.dir = scenario.output.dir;
  std::error_code ec;
  std::filesystem::create_directories(outcome.dir, ec);
  if (ec)
    throw RunError("cannot create run directory " + outcome.dir.string() + ": " + ec.message());
  std::filesystem::remove(outcome.dir / kSummaryFile, ec);  // a stale summary would look current

  write_file_atomically(outcome.dir / kResolvedScenarioFile, to_yaml(scenario.resolved));
  RunLog log(outcome.dir / kLogFile);
  log.line("SwarmNet run of scenario '" + scenario.name + "' from " + scenario.source.string());
  log.line("seed " + std::to_string(scenario.seed) + ", " + std::to_string(scenario.robots.count) +
           " robots, " + std::to_string(scenario.step_count()) + " steps, sync " +
           to_string(scenario.sync));

  const auto wall_start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  try {
    PluginLoader loader(scenario.plugin_paths);
    log_plugins(log, scenario, loader);
    RobotWorld world(scenario, loader);

    std::optional<AtomicFile> mobility_file;
    std::optional<MobilityTraceWriter> mobility;
    if (scenario.output.mobility_trace) {
      mobility_file.emplace(outcome.dir / kMobilityTraceFile);
      const auto interval = static_cast<std::uint64_t>(
          std::llround(scenario.output.mobility_interval_s / scenario.step_s));
      mobility.emplace(mobility_file->stream(), interval, scenario.step_s);
    }
    // Exact positions of every step beside the rounded ns-2 trace, for `swarmnet replay`.
    std::optional<AtomicFile> positions_file;
    std::optional<PositionsTraceWriter> positions;
    if (scenario.output.mobility_trace) {
      positions_file.emplace(outcome.dir / kPositionsTraceFile);
      positions.emplace(positions_file->stream(), scenario.robots.count, scenario.step_count(),
                        from_seconds(scenario.step_s));
    }
    std::optional<AtomicFile> traffic_file;
    std::optional<TrafficScheduleWriter> traffic;
    if (scenario.output.traffic_schedule) {
      traffic_file.emplace(outcome.dir / kTrafficScheduleFile);
      traffic.emplace(traffic_file->stream(), scenario.seed, from_seconds(scenario.step_s));
    }

    for (const std::string& name : remove_stale_segments()) {
      log.line("removed /dev/shm/" + name + ", left behind by a run that crashed");
    }
    const auto link = open_network_link(scenario, outcome.dir, options.link);
    StepChannel channel(link->transport(), "the network half");
    log.line("transport: " + link->describe());

    RobotLoopCost cost;
    std::string report_text;
    std::string robot_error;
    bool lost_peer = false;
    {
      ProgressLine progress(options.progress, scenario.step_count(), scenario.step_s);
      try {
        handshake(scenario, outcome.dir, channel);
        link->connected();
        report_text = drive_robot_half(scenario, world, channel, mobility ? &*mobility : nullptr,
                                       positions ? &*positions : nullptr,
                                       traffic ? &*traffic : nullptr, progress, cost);
      } catch (const PeerLost& error) {
        robot_error = error.what();
        lost_peer = true;
      } catch (const std::exception& error) {
        robot_error = error.what();
        channel.send_failure("the robot half stopped: " + robot_error);
      }
      channel.transport().close();
    }
    const std::string network_error = link->finish();
    if (const int signal = stop_signal(); signal != 0) {
      throw RunError(std::string("interrupted by ") + (signal == SIGINT ? "SIGINT" : "SIGTERM"));
    }
    // When the robot half lost the network half without being told why, how the network half
    // ended (its exit status) is the explanation; otherwise the first account is the clearest.
    if (!robot_error.empty()) {
      const bool unexplained = lost_peer && !channel.peer_failed() && !network_error.empty();
      throw RunError(unexplained ? robot_error + "; " + network_error : robot_error);
    }
    if (!network_error.empty()) throw RunError(network_error);

    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    const double robot_cpu = thread_cpu_seconds() - cpu_start - cost.transport_cpu_s;
    const auto report = nlohmann::ordered_json::parse(report_text);
    const double network_cpu = report["cpu_s"]["network"].get<double>();
    const double transport_cpu = cost.transport_cpu_s + report["cpu_s"]["transport"].get<double>();
    const double sim_s = static_cast<double>(scenario.step_count()) * scenario.step_s;

    if (mobility_file) mobility_file->commit();
    if (positions_file) positions_file->commit();
    if (traffic_file) traffic_file->commit();

    nlohmann::ordered_json& s = outcome.summary;
    s["scenario"] = scenario.name;
    s["scenario_file"] = scenario.source.string();
    s["seed"] = scenario.seed;
    s["robots"] = scenario.robots.count;
    s["sim_time_s"] = sim_s;
    s["step_s"] = scenario.step_s;
    s["steps"] = scenario.step_count();
    s["sync"] = to_string(scenario.sync);
    s["transport"] =
        options.link.remote.empty() ? to_string(options.link.kind) : options.link.remote;
    s["wall_s"] = wall_s;
    s["cpu_s"] = {{"robot", robot_cpu},
                  {"network", network_cpu},
                  {"transport", transport_cpu},
                  {"total", robot_cpu + network_cpu + transport_cpu}};
    s["realtime_factor"] = wall_s > 0 ? sim_s / wall_s : 0.0;
    // CPU both halves spent encoding, moving and waiting on records, as a share of the run.
    s["transport_share"] = wall_s > 0 ? transport_cpu / wall_s : 0.0;
    for (const char* key : {"packets", "pdr", "delay_s", "hops_mean", "mac", "routing", "events"}) {
      if (report.contains(key)) s[key] = report[key];
    }
    s["controllers"] = controller_metrics_json(world);
    nlohmann::ordered_json outputs = {
        {"summary", kSummaryFile}, {"scenario", kResolvedScenarioFile}, {"log", kLogFile}};
    if (scenario.output.packet_trace) outputs["packet_trace"] = kPacketTraceFile;
    if (scenario.output.mobility_trace) {
      outputs["mobility_trace"] = kMobilityTraceFile;
      outputs["positions"] = kPositionsTraceFile;
    }
    if (scenario.output.traffic_schedule) outputs["traffic_schedule"] = kTrafficScheduleFile;
    s["outputs"] = outputs;

    log.line("finished: " + std::to_string(scenario.step_count()) + " steps");
    log.commit();
    // Last, so that a summary.json is present only when every other output is complete.
    write_file_atomically(outcome.dir / kSummaryFile, s.dump(2) + "\n");
  } catch (const std::exception& error) {
    // Both halves have stopped by now; a network half that was killed could not remove its own.
    remove_partial_files(outcome.dir);
    log.line(std::string("run failed: ") + error.what());
    try {
      log.commit();
    } catch (const std::exception&) {
      // The run's own error is the one to report.
    }
    throw;
  }
  return outcome;
}

void print_summary(std::FILE* out, const RunOutcome& outcome) {
  const auto& s = outcome.summary;
  const auto& packets = s["packets"];
  std::fprintf(out, "SwarmNet run '%s' (seed %" PRIu64 ")\n",
               s["scenario"].get<std::string>().c_str(), s["seed"].get<std::uint64_t>());
  std::fprintf(out, "  robots        %u\n", s["robots"].get<unsigned>());
  std::fprintf(out, "  simulated     %.1f s in %" PRIu64 " steps of %g s (%s sync)\n",
               s["sim_time_s"].get<double>(), s["steps"].get<std::uint64_t>(),
               s["step_s"].get<double>(), s["sync"].get<std::string>().c_str());
  std::fprintf(out, "  wall time     %.2f s, %.1fx real time\n", s["wall_s"].get<double>(),
               s["realtime_factor"].get<double>());
  std::fprintf(out, "  CPU           robot %.2f s, network %.2f s, transport %.3f s\n",
               s["cpu_s"]["robot"].get<double>(), s["cpu_s"]["network"].get<double>(),
               s["cpu_s"]["transport"].get<double>());
  std::fprintf(out,
               "  messages      %" PRIu64 " sent, %" PRIu64 " delivered, delivery ratio %.1f%%\n",
               packets["sent"].get<std::uint64_t>(), packets["delivered"].get<std::uint64_t>(),
               100.0 * s["pdr"].get<double>());
  const auto& delay = s["delay_s"];
  if (!delay["mean"].is_null()) {
    std::fprintf(out, "  delay         mean %.2f ms, median %.2f ms, 95th percentile %.2f ms\n",
                 1e3 * delay["mean"].get<double>(), 1e3 * delay["p50"].get<double>(),
                 1e3 * delay["p95"].get<double>());
    std::fprintf(out, "  hops          %.2f on average\n", s["hops_mean"].get<double>());
  }
  std::fprintf(out, "  outputs       %s/ (summary.json, run.log, ...)\n",
               outcome.dir.string().c_str());
}

}  // namespace swarmnet
