// The network half (DESIGN.md section 1): one node per robot, discrete events in integer
// nanoseconds, run one step window at a time by the step protocol (section 2).
//
//   NetworkSettings ──► NetworkSimulator ── nodes: app ↔ routing ↔ mac ↔ phy ↔ channel ↔
//   propagation
//
// A run is a pure function of its settings and the batches: every random draw comes from a
// stream derived with derive_seed from settings.seed and stable keys, events at one instant run in
// scheduling order, and nothing that reaches the output or the event order iterates an unordered
// container.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

#include "network/application_layer.hpp"
#include "network/channel.hpp"
#include "network/frame_trace.hpp"
#include "network/neighbor_tables.hpp"
#include "network/network_engine.hpp"
#include "network/network_metrics.hpp"
#include "network/network_settings.hpp"
#include "network/node.hpp"
#include "network/packet_trace.hpp"
#include "network/packet_uid_source.hpp"
#include "network/scheduler.hpp"
#include "network/sensing_trace.hpp"
#include "plugin/plugin_loader.hpp"
#include "protocol/step_data.hpp"

namespace swarmnet {

class NetworkSimulator final : public NetworkEngine {
 public:
  // `packet_trace`, `frame_trace` and `sensing_trace` may be null (no trace); each must outlive
  // finish(). Creates
  // one node per robot, one MAC and one routing instance per node, and the propagation chain, then
  // calls attach() on every node's MAC and routing (node order). Per-node plugin seeds:
  // derive_seed(settings.seed, {hash_name(kind), hash_name(plugin name), node}).
  // Throws PluginError or std::invalid_argument on a bad set-up.
  NetworkSimulator(const NetworkSettings& settings, PluginLoader& loader,
                   std::ostream* packet_trace, std::ostream* frame_trace = nullptr,
                   std::ostream* sensing_trace = nullptr);
  NetworkSimulator(const NetworkSimulator&) = delete;
  NetworkSimulator& operator=(const NetworkSimulator&) = delete;
  NetworkSimulator(NetworkSimulator&&) = delete;
  NetworkSimulator& operator=(NetworkSimulator&&) = delete;
  ~NetworkSimulator() override;

  // Simulates [batch.start, batch.start + step): places the nodes at batch.positions (held over
  // the window), injects each message at batch.start + injection_offset(seed, message id, step),
  // runs every event before the window's end and fills `result` (step, deliveries in delivery
  // order, events run in the window). batch.start must not be before the end of the previous
  // window; a batch with the wrong number of positions, or a message or a route query naming an
  // unknown robot, is refused with std::invalid_argument before anything is simulated. Route
  // queries are answered at the window's end (result.routes). With a sensing trace, what
  // `result` holds for the robot half's controllers is written to it (network/sensing_trace.hpp).
  void run_step(const StepBatch& batch, StepResult& result) override;

  // Metrics so far (keys and definitions: network_metrics.hpp).
  [[nodiscard]] NetworkReport report() const override;

  // Flushes the packet, frame and sensing traces (they have no footer); call once, at the end.
  void finish() override;

  [[nodiscard]] SimTime now() const { return scheduler_.now(); }
  // A stop flag the event loop polls (Scheduler::set_interrupt_check): a stop signal ends even a
  // window of millions of events promptly, with SimulationInterrupted.
  void set_interrupt_check(Scheduler::InterruptCheck check) {
    scheduler_.set_interrupt_check(check);
  }
  [[nodiscard]] SimTime step_length() const { return step_; }
  [[nodiscard]] std::size_t node_count() const { return nodes_.size(); }
  [[nodiscard]] const Channel& channel() const { return channel_; }
  [[nodiscard]] const NetworkMetrics& metrics() const { return metrics_; }
  [[nodiscard]] std::uint64_t events() const { return scheduler_.events_run(); }

 private:
  void check_batch(const StepBatch& batch) const;
  // Asks each query's node's routing plugin (Routing::route_to) now, at the window's end;
  // throws std::logic_error, naming the plugin, for an answer no protocol may give.
  void answer_route_queries(std::span<const RouteQuery> queries,
                            std::vector<RouteAnswer>& answers) const;

  std::uint64_t traffic_seed_;  // places injections in their step (NetworkSettings)
  std::string routing_name_;    // network.routing's plugin, for errors in its answers
  SimTime step_;
  // Declared first, destroyed last; the destructor clears it before the plugins go, so no
  // callback made by a plugin's code outlives the plugin's library.
  Scheduler scheduler_;
  NetworkMetrics metrics_;
  PacketTraceWriter trace_;
  FrameTraceWriter frames_;
  SensingTraceWriter sensing_;
  PacketUidSource packet_uids_;
  SendReports send_reports_;
  Channel channel_;
  ApplicationLayer application_;
  std::optional<NeighborTables> neighbors_;  // network.neighbors.enabled
  std::vector<std::unique_ptr<Node>> nodes_;
};

}  // namespace swarmnet
