#include "coupling/network_half.hpp"

#include <memory>
#include <optional>

#include "coupling/cpu_clock.hpp"
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

void serve(const Scenario& scenario, PluginLoader& loader, StepChannel& channel,
           const std::filesystem::path& run_dir, bool stops_on_signal) {
  const double cpu_start = thread_cpu_seconds();
  double transport_cpu = 0.0;
  std::optional<AtomicFile> trace;
  std::optional<AtomicFile> frames;
  if (scenario.output.packet_trace) trace.emplace(run_dir / kPacketTraceFile);
  if (scenario.output.frame_trace) frames.emplace(run_dir / kFrameTraceFile);
  const std::unique_ptr<NetworkEngine> engine = make_network_engine(
      scenario, loader, trace ? &trace->stream() : nullptr, frames ? &frames->stream() : nullptr,
      stops_on_signal ? &stop_requested : nullptr);
  NetworkEngine& simulator = *engine;

  StepBatch batch;
  StepResult result;
  for (;;) {
    bool finished = false;
    const double before_receive = thread_cpu_seconds();
    const ProtocolResult received = channel.receive_batch(batch, finished);
    transport_cpu += thread_cpu_seconds() - before_receive;
    if (!received.ok()) throw RunError(received.error);
    if (finished) break;
    if (stops_on_signal && stop_requested()) throw RunError(stopped_by_signal());
    try {
      simulator.run_step(batch, result);
    } catch (const SimulationInterrupted& interrupted) {
      throw RunError(stopped_by_signal() + " (" + interrupted.what() + ")");
    }
    const double before_send = thread_cpu_seconds();
    const ProtocolResult sent = channel.send_result(result);
    transport_cpu += thread_cpu_seconds() - before_send;
    if (!sent.ok()) throw RunError(sent.error);
  }
  simulator.finish();
  if (trace) trace->commit();
  if (frames) frames->commit();

  NetworkReport report = simulator.report();
  const double total_cpu = thread_cpu_seconds() - cpu_start;
  report.network_cpu_s = total_cpu - transport_cpu;
  report.transport_cpu_s = transport_cpu;
  const ProtocolResult sent = channel.send_report(report);
  if (!sent.ok()) throw RunError(sent.error);
}

}  // namespace

Welcome welcome_for(const Scenario& scenario) {
  return Welcome{scenario.seed, scenario.robots.count, from_seconds(scenario.step_s).count()};
}

void serve_network_half(const Scenario& scenario, PluginLoader& loader, StepChannel& channel,
                        const std::filesystem::path& run_dir, bool stops_on_signal) {
  try {
    serve(scenario, loader, channel, run_dir, stops_on_signal);
  } catch (const std::exception& error) {
    channel.send_failure(error.what());
    channel.transport().close();
    throw RunError(std::string("network half: ") + error.what());
  }
  channel.transport().close();
}

void serve_network_connection(StepChannel& channel,
                              const std::function<NetworkSetup(const Hello&)>& setup) {
  Hello hello;
  std::optional<NetworkSetup> accepted;
  try {
    const ProtocolResult received = channel.receive_hello(hello);
    if (!received.ok()) throw RunError(received.error);
    accepted.emplace(setup(hello));
    const ProtocolResult sent = channel.send_welcome(welcome_for(accepted->scenario));
    if (!sent.ok()) throw RunError(sent.error);
  } catch (const std::exception& error) {
    channel.send_failure(error.what());
    channel.transport().close();
    throw RunError(std::string("network half: ") + error.what());
  }
  serve_network_half(accepted->scenario, *accepted->loader, channel, accepted->run_dir,
                     accepted->stops_on_signal);
}

}  // namespace swarmnet
