#include "coupling/network_half.hpp"

#include <memory>
#include <new>
#include <optional>

#include "coupling/cpu_clock.hpp"
#include "coupling/memory_budget.hpp"
#include "coupling/network_engine_choice.hpp"
#include "coupling/stop_signal.hpp"
#include "network/scheduler.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/output_files.hpp"
#include "outputs/run_error.hpp"
#include "plugin/plugin_loader.hpp"

namespace swarmnet {

namespace {

bool stop_requested() { return stop_signal() != 0; }

// The reason a run stopped on a signal, for the peer and the log.
std::string stopped_by_signal() {
  return std::string("stopped by ") + stop_signal_name(stop_signal()) +
         " on the network half's host";
}

// What a run's network half holds from its set-up to its end: the engine and its trace files.
struct NetworkRun {
  std::optional<AtomicFile> trace;
  std::optional<AtomicFile> frames;
  std::optional<AtomicFile> sensing;
  std::unique_ptr<NetworkEngine> engine;
  double cpu_start = 0.0;  // thread CPU time when the set-up began
};

// Builds the engine, the run's fixed cost (nodes, plugins, tables), before the welcome: a
// scenario that does not fit in memory is refused before its first step.
void open_run(NetworkRun& run, const NetworkSetup& setup) {
  run.cpu_start = thread_cpu_seconds();
  const Scenario& scenario = setup.scenario;
  const std::uint64_t heap_before = heap_in_use_bytes();
  try {
    if (scenario.output.packet_trace) run.trace.emplace(setup.run_dir / kPacketTraceFile);
    if (scenario.output.frame_trace) run.frames.emplace(setup.run_dir / kFrameTraceFile);
    if (scenario.output.sensing_trace) run.sensing.emplace(setup.run_dir / kSensingTraceFile);
    const NetworkTraceStreams traces{run.trace ? &run.trace->stream() : nullptr,
                                     run.frames ? &run.frames->stream() : nullptr,
                                     run.sensing ? &run.sensing->stream() : nullptr};
    run.engine = make_network_engine(scenario, *setup.loader, traces,
                                     setup.stops_on_signal ? &stop_requested : nullptr);
  } catch (const std::bad_alloc&) {
    const std::uint64_t heap_now = heap_in_use_bytes();
    const std::uint64_t reached = heap_now > heap_before ? heap_now - heap_before : 0;
    run.engine.reset();
    throw RunError("the network of " + std::to_string(scenario.robots.count) +
                   " robots needs more memory than " + setup.memory_limit +
                   " allows: its set-up had taken " + describe_bytes(reached) +
                   " when an allocation failed; refused before the first step");
  }
}

void serve(NetworkRun& run, const NetworkSetup& setup, StepChannel& channel) {
  // The transport's CPU runs from before a result is sent to after the next batch arrived: two
  // reads of the thread's CPU clock (a system call) a step instead of four.
  double transport_cpu = 0.0;
  double transport_since = thread_cpu_seconds();
  NetworkEngine& simulator = *run.engine;
  StepBatch batch;
  StepResult result;
  for (;;) {
    bool finished = false;
    const ProtocolResult received = channel.receive_batch(batch, finished);
    transport_cpu += thread_cpu_seconds() - transport_since;
    if (!received.ok()) throw RunError(received.error);
    if (finished) break;
    if (setup.stops_on_signal && stop_requested()) throw RunError(stopped_by_signal());
    try {
      simulator.run_step(batch, result);
    } catch (const SimulationInterrupted& interrupted) {
      throw RunError(stopped_by_signal() + " (" + interrupted.what() + ")");
    } catch (const std::bad_alloc&) {
      throw RunError("ran out of memory in step " + std::to_string(batch.step) + " (" +
                     setup.memory_limit + ")");
    }
    transport_since = thread_cpu_seconds();
    const ProtocolResult sent = channel.send_result(result);
    if (!sent.ok()) throw RunError(sent.error);
  }
  simulator.finish();
  for (std::optional<AtomicFile>* file : {&run.trace, &run.frames, &run.sensing}) {
    if (!*file) continue;
    if (setup.traces == TraceCommit::by_robot_half) {
      (*file)->hand_over();
    } else {
      (*file)->commit();
    }
  }

  NetworkReport report = simulator.report();
  const double total_cpu = thread_cpu_seconds() - run.cpu_start;
  report.network_cpu_s = total_cpu - transport_cpu;
  report.transport_cpu_s = transport_cpu;
  const ProtocolResult sent = channel.send_report(report);
  if (!sent.ok()) throw RunError(sent.error);
}

[[noreturn]] void fail(StepChannel& channel, const std::exception& error) {
  channel.send_failure(error.what());
  channel.transport().close();
  throw RunError(std::string("network half: ") + error.what());
}

}  // namespace

Welcome welcome_for(const Scenario& scenario) {
  const NeighborSensing& neighbors = scenario.network.neighbors;
  return Welcome{scenario.seed, scenario.robots.count, from_seconds(scenario.step_s).count(),
                 neighbors.enabled ? neighbors.max_per_robot : 0};
}

void serve_network_connection(StepChannel& channel,
                              const std::function<NetworkSetup(const Hello&)>& setup,
                              bool* welcomed) {
  Hello hello;
  std::optional<NetworkSetup> accepted;
  std::optional<NetworkRun> run;
  try {
    const ProtocolResult received = channel.receive_hello(hello);
    if (!received.ok()) throw RunError(received.error);
    accepted.emplace(setup(hello));
    open_run(run.emplace(), *accepted);
    if (accepted->step_payload_limit != 0) channel.limit_step_payload(accepted->step_payload_limit);
    const ProtocolResult sent = channel.send_welcome(welcome_for(accepted->scenario));
    if (!sent.ok()) throw RunError(sent.error);
    if (welcomed != nullptr) *welcomed = true;
  } catch (const std::exception& error) {
    fail(channel, error);
  }
  try {
    serve(*run, *accepted, channel);
  } catch (const std::exception& error) {
    run.reset();  // the engine's memory goes before the failure is reported
    fail(channel, error);
  }
  channel.transport().close();
}

}  // namespace swarmnet
