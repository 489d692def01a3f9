#include "session/run.hpp"

#include <unistd.h>

#include <chrono>
#include <cinttypes>
#include <csignal>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>
#include <utility>

#include "coupling/core_pairing.hpp"
#include "coupling/cpu_clock.hpp"
#include "coupling/network_half.hpp"
#include "coupling/network_link.hpp"
#include "coupling/socket_directory.hpp"
#include "coupling/stop_signal.hpp"
#include "display/progress_line.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/headings_trace.hpp"
#include "outputs/mobility_trace.hpp"
#include "outputs/object_trace.hpp"
#include "outputs/output_commit.hpp"
#include "outputs/output_files.hpp"
#include "outputs/positions_trace.hpp"
#include "outputs/run_directory.hpp"
#include "outputs/run_error.hpp"
#include "outputs/run_log.hpp"
#include "outputs/run_summary.hpp"
#include "outputs/traffic_schedule.hpp"
#include "plugin/plugin_loader.hpp"
#include "protocol/step_channel.hpp"
#include "robot/robot_world.hpp"
#include "shm_segment.hpp"

namespace swarmnet {

namespace {

// The channel to the network half failed; distinct from a failure of the robot half itself.
class PeerLost : public RunError {
 public:
  using RunError::RunError;
};

// How many steps later the robot half reads a window's deliveries (DESIGN.md section 2).
std::uint64_t delivery_lag(SyncMode mode) { return mode == SyncMode::strict ? 1 : 2; }

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
  for (const auto& world : scenario.worlds) describe(world);
  for (const auto& controller : scenario.robots.controllers) describe(controller);
  for (const auto& model : scenario.network.propagation) describe(model);
  describe(scenario.network.mac);
  describe(scenario.network.routing);
}

// Removes the files left under a temporary name (AtomicFile's ".partial-PID") in `dir`: the
// network half's (it may have been killed) and those handed over to be committed; the log being
// written (`log`) stays.
void remove_partial_files(const std::filesystem::path& dir, const std::filesystem::path& log) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (is_leftover_file(entry.path().filename().string()) &&
        entry.path().filename() != log.filename()) {
      std::filesystem::remove(entry.path(), ec);
    }
  }
}

void handshake(const Scenario& scenario, const std::filesystem::path& run_dir,
               StepChannel& channel) {
  Hello hello;
  hello.scenario_yaml = scenario.resolved_yaml;
  hello.run_dir = std::filesystem::absolute(run_dir).string();
  if (const ProtocolResult r = channel.send_hello(hello); !r.ok()) throw PeerLost(r.error);
  if (const ProtocolResult r = channel.receive_welcome(welcome_for(scenario)); !r.ok())
    throw PeerLost(r.error);
}

// What driving the robot half cost and how far it went.
struct RobotLoop {
  double transport_cpu_s = 0.0;
  std::uint64_t steps = 0;  // steps run: the scenario's, or fewer when a world's task was done
};

// Drives the robot half over `channel` for every step, or until a world plugin's task is done;
// returns the network half's report.
NetworkReport drive_robot_half(const Scenario& scenario, RobotWorld& world, StepChannel& channel,
                               MobilityTraceWriter* mobility, PositionsTraceWriter* positions,
                               HeadingsTraceWriter* headings, ObjectTraceWriter* objects,
                               TrafficScheduleWriter* traffic, ProgressLine& progress, RunLog& log,
                               CorePairing* pairing, RobotLoop& loop) {
  const std::uint64_t steps = scenario.step_count();
  const std::uint64_t lag = delivery_lag(scenario.sync);
  StepBatch batch;
  StepResult result;
  std::vector<Delivery> no_deliveries;

  // The transport's CPU runs from before a batch is sent to after the next result arrived: two
  // clock reads a step instead of four (on a light run, reading the thread's CPU clock is a
  // system call that costs as much as a hand-over). In between lies only the loop's bookkeeping.
  double transport_since = -1.0;  // thread CPU when the open stretch began; < 0: none open
  auto transport_begins = [&] {
    if (transport_since < 0.0) transport_since = thread_cpu_seconds();
  };
  auto transport_ends = [&] {
    if (transport_since < 0.0) return;
    loop.transport_cpu_s += thread_cpu_seconds() - transport_since;
    transport_since = -1.0;
  };
  auto receive = [&](std::uint64_t expected_step) {
    transport_begins();
    const ProtocolResult received = channel.receive_result(result);
    transport_ends();
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
      world.set_neighbor_tables(result.neighbor_counts, result.neighbors);
      world.set_send_reports(result.send_reports);
      world.set_routes(result.routes);
    }
    batch.step = step;
    batch.start = world.now();
    const auto bodies = world.bodies();
    batch.positions.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) batch.positions[i] = bodies[i].position;
    if (mobility != nullptr) mobility->sample(step, batch.positions);
    if (positions != nullptr) positions->sample(batch.positions);
    if (headings != nullptr) headings->sample(bodies);
    if (objects != nullptr) objects->sample(step, world.object_poses());

    batch.messages.clear();
    world.step(*deliveries, batch.messages);
    world.take_route_queries(batch.route_queries);
    if (traffic != nullptr) traffic->write(batch);

    progress.update(step + 1);
    log.progress(step + 1, steps, scenario.step_s);
    transport_begins();
    const ProtocolResult sent = channel.send_batch(batch);
    if (!sent.ok()) throw PeerLost(sent.error);
    loop.steps = step + 1;
    if (pairing != nullptr) pairing->tick(std::chrono::steady_clock::now());
    if (world.task_done()) break;
  }
  // Windows whose deliveries no robot step will read any more: still simulated and counted.
  const std::uint64_t ran = loop.steps;
  for (std::uint64_t step = ran > lag ? ran - lag : 0; step < ran; ++step) receive(step);
  transport_ends();
  if (const ProtocolResult r = channel.send_finish(); !r.ok()) throw PeerLost(r.error);
  NetworkReport report;
  if (const ProtocolResult r = channel.receive_report(report); !r.ok()) throw PeerLost(r.error);
  return report;
}

}  // namespace

RunOutcome run_scenario(const Scenario& scenario, PluginLoader& loader, const RunOptions& options) {
  RunOutcome outcome;
  outcome.dir = scenario.output.dir;
  const std::vector<std::string> notes = prepare_run_directory(outcome.dir, options.overwrite);

  // First, with its room reserved: whatever fails after this (a full disk too), run.log says why.
  RunLog log(outcome.dir / kLogFile);
  const auto wall_start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  try {
    log.line("SwarmNet run of scenario '" + scenario.name + "' from " + scenario.source.string());
    for (const std::string& note : notes) log.line(note);
    log.line("seed " + std::to_string(scenario.seed) + ", " +
             std::to_string(scenario.robots.count) + " robots, " +
             std::to_string(scenario.step_count()) + " steps, sync " + to_string(scenario.sync));
    // Under its final name from the start, as run.log: both say what ran, also when it failed.
    write_file_atomically(outcome.dir / kResolvedScenarioFile, scenario.resolved_yaml);
    log_plugins(log, scenario, loader);
    std::optional<AtomicFile> series_file;  // only once a plugin sampled
    RobotSettings robot_settings = scenario.robot_settings();
    robot_settings.open_series = [&]() -> std::ostream& {
      series_file.emplace(outcome.dir / kSeriesFile);
      return series_file->stream();
    };
    RobotWorld world(robot_settings, loader);

    std::optional<AtomicFile> mobility_file;
    std::optional<MobilityTraceWriter> mobility;
    if (scenario.output.mobility_trace) {
      mobility_file.emplace(outcome.dir / kMobilityTraceFile);
      const auto interval = static_cast<std::uint64_t>(
          std::llround(scenario.output.mobility_interval_s / scenario.step_s));
      mobility.emplace(mobility_file->stream(), interval, scenario.step_s);
    }
    // Exact positions of every step beside the rounded ns-2 trace, for `swarmnet replay`, and
    // the headings beside them, for the viewer.
    std::optional<AtomicFile> positions_file;
    std::optional<PositionsTraceWriter> positions;
    std::optional<AtomicFile> headings_file;
    std::optional<HeadingsTraceWriter> headings;
    if (scenario.output.mobility_trace) {
      const SimTime step = from_seconds(scenario.step_s);
      positions_file.emplace(outcome.dir / kPositionsTraceFile);
      positions.emplace(positions_file->stream(), scenario.robots.count, scenario.step_count(),
                        step);
      headings_file.emplace(outcome.dir / kHeadingsTraceFile);
      headings.emplace(headings_file->stream(), scenario.robots.count, scenario.step_count(), step);
    }
    // The movable objects' poses, written with the robots' positions.
    std::optional<AtomicFile> objects_file;
    std::optional<ObjectTraceWriter> objects;
    if (scenario.output.mobility_trace && !scenario.arena.objects.empty()) {
      objects_file.emplace(outcome.dir / kObjectTraceFile);
      objects.emplace(objects_file->stream(), from_seconds(scenario.step_s));
    }
    std::optional<AtomicFile> traffic_file;
    std::optional<AtomicFile> send_options_file;   // only once a message had options
    std::optional<AtomicFile> route_queries_file;  // only once a controller asked route_to()
    std::optional<TrafficScheduleWriter> traffic;
    if (scenario.output.traffic_schedule) {
      traffic_file.emplace(outcome.dir / kTrafficScheduleFile);
      traffic.emplace(
          traffic_file->stream(), scenario.seed, from_seconds(scenario.step_s),
          [&]() -> std::ostream& {
            send_options_file.emplace(outcome.dir / kSendOptionsFile);
            return send_options_file->stream();
          },
          [&]() -> std::ostream& {
            route_queries_file.emplace(outcome.dir / kRouteQueriesFile);
            return route_queries_file->stream();
          },
          scenario.output.sensing_trace);
    }

    for (const std::string& name : remove_stale_segments()) {
      log.line("removed /dev/shm/" + name + ", left behind by a run that crashed");
    }
    for (const auto& directory : remove_stale_socket_directories()) {
      log.line("removed " + directory.string() + ", left behind by a run that crashed");
    }
    const auto link = open_network_link(scenario, loader, outcome.dir, options.link);
    StepChannel channel(link->transport(), "the network half");
    log.line("transport: " + link->describe());

    RobotLoop loop;
    NetworkReport report;
    std::string robot_error;
    bool lost_peer = false;
    {
      ProgressLine progress(options.progress, scenario.step_count(), scenario.step_s);
      try {
        handshake(scenario, outcome.dir, channel);
        link->connected();
        // Strict halves take turns: one core serves both (core_pairing.hpp).
        std::optional<CorePairing> pairing;
        if (scenario.sync == SyncMode::strict) pairing.emplace(link->network_thread());
        report =
            drive_robot_half(scenario, world, channel, mobility ? &*mobility : nullptr,
                             positions ? &*positions : nullptr, headings ? &*headings : nullptr,
                             objects ? &*objects : nullptr, traffic ? &*traffic : nullptr, progress,
                             log, pairing ? &*pairing : nullptr, loop);
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
    // A send that found the channel closed does not see the reason the network half left in it
    // before it stopped (e.g. it timed out waiting for this half): read it now that it is gone.
    if (lost_peer && !channel.peer_failed()) {
      if (std::string reason = channel.drain_for_failure(); !reason.empty()) robot_error = reason;
    }
    if (const int signal = stop_signal(); signal != 0) {
      throw RunError(std::string("interrupted by ") + stop_signal_name(signal));
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
    const double robot_cpu = thread_cpu_seconds() - cpu_start - loop.transport_cpu_s;

    world.end_worlds();
    if (positions) positions->finish();
    if (headings) headings->finish();
    // Every output is written and synced under its temporary name before any is renamed, so
    // that a failure (a full disk) leaves none under its final name.
    OutputCommit commit;
    if (mobility_file) commit.add(*mobility_file);
    if (positions_file) commit.add(*positions_file);
    if (headings_file) commit.add(*headings_file);
    if (objects_file) commit.add(*objects_file);
    if (traffic_file) commit.add(*traffic_file);
    if (send_options_file) commit.add(*send_options_file);
    if (route_queries_file) commit.add(*route_queries_file);
    if (series_file) commit.add(*series_file);
    std::optional<AtomicFile> robot_metrics_file;
    if (!world.robot_metrics().empty()) {
      robot_metrics_file.emplace(outcome.dir / kRobotMetricsFile);
      world.robot_metrics().write_csv(robot_metrics_file->stream());
      commit.add(*robot_metrics_file);
    }
    std::optional<AtomicFile> view_file;
    if (!world.view_record().empty()) {
      view_file.emplace(outcome.dir / kViewStatesFile);
      world.view_record().write_csv(view_file->stream());
      commit.add(*view_file);
    }
    // The network half beside this one finished its traces under its own temporary names and
    // left their renaming to this half; a remote one commits them on its own host.
    if (const pid_t network = link->local_network_pid(); network > 0) {
      const std::string suffix = ".partial-" + std::to_string(network);
      const std::pair<bool, const char*> traces[] = {
          {scenario.output.packet_trace, kPacketTraceFile},
          {scenario.output.frame_trace, kFrameTraceFile},
          {scenario.output.sensing_trace, kSensingTraceFile}};
      for (const auto& [wanted, name] : traces) {
        if (wanted) commit.add(outcome.dir / (std::string(name) + suffix), outcome.dir / name);
      }
    }

    SummaryInputs summary;
    summary.scenario = &scenario;
    summary.transport =
        options.link.remote.empty() ? to_string(options.link.kind) : options.link.remote;
    summary.timings = {wall_s, robot_cpu, report.network_cpu_s,
                       loop.transport_cpu_s + report.transport_cpu_s};
    summary.network = &report;
    const ControllerMetrics controller_metrics = world.controller_metrics();
    summary.controllers = &controller_metrics;
    summary.steps = loop.steps;
    summary.ended = SummaryInputs::Ended{world.done_by()};
    if (!scenario.worlds.empty()) summary.world = &world.world_metrics();
    outcome.summary = build_summary(summary);

    // Written (and a full disk found) before run.log says the run finished; renamed into place
    // last, so that a summary.json is present only when every other output is complete.
    AtomicFile summary_file(outcome.dir / kSummaryFile);
    summary_file.stream() << outcome.summary.dump(2) << "\n";
    summary_file.finish();
    const std::optional<std::string> done_by = world.done_by();
    log.line("finished: " + std::to_string(loop.steps) + " steps" +
             (done_by ? ", ended by world " + *done_by + ": its task is done" : ""));
    commit.rename_added();
    log.commit();
    commit.add(summary_file);
    commit.rename_added();
    commit.keep();
  } catch (const std::exception& error) {
    // Both halves have stopped by now; a network half that was killed could not remove its own.
    remove_partial_files(outcome.dir, log.temporary());
    log.fail(std::string("run failed: ") + error.what());
    throw;
  }
  return outcome;
}

}  // namespace swarmnet
