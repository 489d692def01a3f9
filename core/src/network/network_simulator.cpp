#include "network/network_simulator.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "swarmnet/random.hpp"

namespace swarmnet {

namespace {

PluginArgs node_plugin_args(const NetworkSettings& settings, const PluginChoice& choice,
                            NodeId node) {
  PluginArgs args;
  args.params = choice.params;
  const std::uint64_t kind = hash_name(to_string(choice.kind));
  const std::uint64_t name = hash_name(choice.name.c_str());
  args.seed = derive_seed(settings.seed, {kind, name, node});
  args.shared_seed = derive_seed(settings.seed, {kind, name});
  args.instance = node;
  args.instance_count = settings.nodes;
  return args;
}

SimTime checked_step(const NetworkSettings& settings) {
  const SimTime step = from_seconds(settings.step_s);
  if (step <= kTimeZero) {
    throw std::invalid_argument("network: step_s must be at least 1 ns (got " +
                                std::to_string(settings.step_s) + ")");
  }
  return step;
}

}  // namespace

NetworkSimulator::NetworkSimulator(const NetworkSettings& settings, PluginLoader& loader,
                                   std::ostream* packet_trace, std::ostream* frame_trace,
                                   std::ostream* sensing_trace)
    : traffic_seed_(settings.traffic_seed),
      routing_name_(settings.network.routing.name),
      step_(checked_step(settings)),
      trace_(packet_trace),
      frames_(frame_trace),
      sensing_(sensing_trace),
      channel_(settings, PropagationChain(settings, loader), scheduler_, settings.nodes),
      application_(settings.nodes, metrics_, trace_, packet_uids_, send_reports_) {
  if (settings.network.neighbors.enabled) {
    neighbors_.emplace(settings.nodes, settings.network.neighbors);
  }
  const NodeServices services{scheduler_,
                              channel_,
                              application_,
                              trace_,
                              frames_,
                              metrics_,
                              packet_uids_,
                              send_reports_,
                              derive_seed(settings.seed, {hash_name("phy")}),
                              derive_seed(settings.seed, {hash_name("arp")}),
                              neighbors_ ? &*neighbors_ : nullptr};
  PluginChoice mac = settings.network.mac;
  PluginChoice routing = settings.network.routing;
  mac.kind = PluginKind::mac;  // the seed keys name the kind, whatever the struct was filled with
  routing.kind = PluginKind::routing;
  nodes_.reserve(settings.nodes);
  for (NodeId id = 0; id < settings.nodes; ++id) {
    auto mac_instance = loader.create<Mac>(mac.name, node_plugin_args(settings, mac, id));
    auto routing_instance =
        loader.create<Routing>(routing.name, node_plugin_args(settings, routing, id));
    nodes_.push_back(std::make_unique<Node>(id, services, settings.network.phy,
                                            settings.network.arp, std::move(mac_instance),
                                            std::move(routing_instance)));
    channel_.attach(id, nodes_.back()->phy());
  }
  for (auto& node : nodes_) node->attach();
}

NetworkSimulator::~NetworkSimulator() { scheduler_.clear(); }

void NetworkSimulator::check_batch(const StepBatch& batch) const {
  if (batch.start < scheduler_.now()) {
    throw std::invalid_argument("network: step " + std::to_string(batch.step) + " starts at " +
                                std::to_string(batch.start.count()) +
                                " ns, before the end of the previous window (" +
                                std::to_string(scheduler_.now().count()) + " ns)");
  }
  if (batch.positions.size() != nodes_.size()) {
    throw std::invalid_argument("network: step " + std::to_string(batch.step) + " has " +
                                std::to_string(batch.positions.size()) + " positions for " +
                                std::to_string(nodes_.size()) + " nodes");
  }
  for (const RouteQuery& query : batch.route_queries) {
    if (query.robot >= nodes_.size() || query.destination >= nodes_.size() ||
        query.robot == query.destination) {
      throw std::invalid_argument("network: step " + std::to_string(batch.step) + " asks robot " +
                                  std::to_string(query.robot) + "'s route to " +
                                  std::to_string(query.destination) +
                                  ", which is not another robot");
    }
  }
  for (const AppMessage& message : batch.messages) {
    const bool bad_destination =
        message.destination != kBroadcast && message.destination >= nodes_.size();
    if (message.source >= nodes_.size() || bad_destination) {
      throw std::invalid_argument("network: message " + std::to_string(message.message_id) +
                                  " from robot " + std::to_string(message.source) + " to " +
                                  std::to_string(message.destination) + " names an unknown robot");
    }
  }
}

void NetworkSimulator::run_step(const StepBatch& batch, StepResult& result) {
  check_batch(batch);
  result.step = batch.step;
  result.deliveries.clear();
  application_.set_output(&result.deliveries);
  // Detach the result again however the window ends (a plugin's logic error propagates).
  struct OutputReset {
    ApplicationLayer& application;
    ~OutputReset() { application.set_output(nullptr); }
  } output_reset{application_};

  std::uint64_t events = scheduler_.run_until(batch.start);  // a gap between windows, if any
  channel_.set_positions(batch.positions);
  for (const AppMessage& message : batch.messages) {
    ApplicationLayer::Message pending{message.message_id,
                                      message.source,
                                      message.destination,
                                      message.port,
                                      std::make_shared<const Payload>(message.payload),
                                      message.hop_limit,
                                      message.report};
    Routing& routing = nodes_[message.source]->routing();
    scheduler_.schedule_at(batch.start + injection_offset(traffic_seed_, message.message_id, step_),
                           [this, pending = std::move(pending), &routing] {
                             application_.inject(pending, scheduler_.now(), routing);
                           });
  }
  events += scheduler_.run_until(batch.start + step_);
  if (neighbors_) neighbors_->collect(scheduler_.now(), result.neighbor_counts, result.neighbors);
  result.send_reports.clear();
  send_reports_.collect(result.send_reports);
  answer_route_queries(batch.route_queries, result.routes);
  result.events = events;
  if (sensing_.enabled()) sensing_.record(result, batch.start + step_);

  trace_.flush();
  frames_.flush();
  sensing_.flush();
}

void NetworkSimulator::answer_route_queries(std::span<const RouteQuery> queries,
                                            std::vector<RouteAnswer>& answers) const {
  answers.clear();
  for (const RouteQuery& query : queries) {
    Route route = nodes_[query.robot]->routing().route_to(query.destination);
    if (!is_possible_answer(route, nodes_.size())) {
      throw std::logic_error("network: routing plugin '" + routing_name_ + "' answered node " +
                             std::to_string(query.robot) + "'s route_to(" +
                             std::to_string(query.destination) + ") with status " +
                             std::to_string(static_cast<unsigned>(route.status)) + ", next hop " +
                             std::to_string(route.next_hop) + ", " + std::to_string(route.hops) +
                             " hops (a valid route names a node and at least one hop; pending is "
                             "the kernel's)");
    }
    if (route.status != RouteStatus::valid) route = Route{route.status};
    route.as_of = scheduler_.now();
    answers.push_back(RouteAnswer{query, route});
  }
}

NetworkReport NetworkSimulator::report() const {
  return metrics_.report(application_.undelivered_unicast(), scheduler_.events_run());
}

void NetworkSimulator::finish() {
  trace_.finish();
  frames_.finish();
  sensing_.finish();
}

}  // namespace swarmnet
