#include "coupling/network_half.hpp"

#include <memory>
#include <optional>

#include "coupling/cpu_clock.hpp"
#include "coupling/network_engine_choice.hpp"
#include "outputs/atomic_file.hpp"
#include "outputs/output_files.hpp"
#include "outputs/run_error.hpp"
#include "plugin/plugin_loader.hpp"

namespace swarmnet {

namespace {

void serve(const Scenario& scenario, PluginLoader& loader, StepChannel& channel,
           const std::filesystem::path& run_dir, TraceCommit traces) {
  const double cpu_start = thread_cpu_seconds();
  double transport_cpu = 0.0;
  std::optional<AtomicFile> trace;
  std::optional<AtomicFile> frames;
  if (scenario.output.packet_trace) trace.emplace(run_dir / kPacketTraceFile);
  if (scenario.output.frame_trace) frames.emplace(run_dir / kFrameTraceFile);
  const std::unique_ptr<NetworkEngine> engine = make_network_engine(
      scenario, loader, trace ? &trace->stream() : nullptr, frames ? &frames->stream() : nullptr);
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
    simulator.run_step(batch, result);
    const double before_send = thread_cpu_seconds();
    const ProtocolResult sent = channel.send_result(result);
    transport_cpu += thread_cpu_seconds() - before_send;
    if (!sent.ok()) throw RunError(sent.error);
  }
  simulator.finish();
  for (std::optional<AtomicFile>* file : {&trace, &frames}) {
    if (!*file) continue;
    if (traces == TraceCommit::by_robot_half) {
      (*file)->hand_over();
    } else {
      (*file)->commit();
    }
  }

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
                        const std::filesystem::path& run_dir, TraceCommit traces) {
  try {
    serve(scenario, loader, channel, run_dir, traces);
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
  // A half writing into the robot half's own run directory (a child, a thread) leaves its traces
  // to be committed with the run's other outputs; a server names a directory of its own.
  std::error_code ec;
  const bool beside = std::filesystem::absolute(accepted->run_dir, ec) == hello.run_dir;
  serve_network_half(accepted->scenario, *accepted->loader, channel, accepted->run_dir,
                     beside ? TraceCommit::by_robot_half : TraceCommit::here);
}

}  // namespace swarmnet
