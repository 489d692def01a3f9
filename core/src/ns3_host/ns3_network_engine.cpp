#include "ns3_host/ns3_network_engine.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>
#include <tuple>

#include "network/application_layer.hpp"
#include "network/scheduler.hpp"
#include "ns3_host/ns3_engine_library.hpp"
#include "ns3_host/ns3_settings.hpp"

namespace swarmnet {

namespace {

std::vector<NamedCount> named_counts(const ns3engine::Counters& counters) {
  std::vector<NamedCount> named;
  named.reserve(counters.size());
  for (const auto& [name, value] : counters) named.push_back({name, value});
  return named;
}

}  // namespace

namespace {

ns3engine::Config config_with_stop(const NetworkSettings& settings, bool (*stop_requested)()) {
  ns3engine::Config config = ns3_config_for(settings);
  config.stop_requested = stop_requested;
  return config;
}

}  // namespace

Ns3NetworkEngine::Ns3NetworkEngine(const NetworkSettings& settings, bool (*stop_requested)())
    : traffic_seed_(settings.traffic_seed),
      step_(from_seconds(settings.step_s)),
      nodes_(settings.nodes),
      network_(create_ns3_network(config_with_stop(settings, stop_requested))) {}

void Ns3NetworkEngine::check_batch(const StepBatch& batch) const {
  if (batch.positions.size() != nodes_) {
    throw std::invalid_argument("step " + std::to_string(batch.step) + " has " +
                                std::to_string(batch.positions.size()) + " positions for " +
                                std::to_string(nodes_) + " nodes");
  }
  if (batch.start < next_start_) {
    throw std::invalid_argument("step " + std::to_string(batch.step) +
                                " starts before the end of the previous one");
  }
  for (const auto& message : batch.messages) {
    if (message.source >= nodes_ ||
        (message.destination != kBroadcast && message.destination >= nodes_)) {
      throw std::invalid_argument("message " + std::to_string(message.message_id) +
                                  " names a robot that does not exist");
    }
    if (message.hop_limit != 0 || message.report) {
      throw std::invalid_argument(
          "robot " + std::to_string(message.source) + "'s message " +
          std::to_string(message.message_id) + " asks for " +
          (message.report ? "a send report" : "a hop limit") +
          " (SendOptions); network.engine: ns3 gives neither: run it with the native engine");
    }
  }
  if (!batch.route_queries.empty()) {
    const RouteQuery& query = batch.route_queries.front();
    throw std::invalid_argument("robot " + std::to_string(query.robot) + " asks route_to(" +
                                std::to_string(query.destination) + ") in step " +
                                std::to_string(batch.step) +
                                "; network.engine: ns3 answers no route queries: run it with the "
                                "native engine");
  }
}

void Ns3NetworkEngine::run_step(const StepBatch& batch, StepResult& result) {
  check_batch(batch);
  result.step = batch.step;
  result.deliveries.clear();
  xy_.clear();
  for (const auto& position : batch.positions) {
    xy_.push_back(position.x());
    xy_.push_back(position.y());
  }
  window_messages_.clear();
  arrivals_.clear();
  self_arrivals_.clear();
  for (const auto& message : batch.messages) {
    const SimTime at = batch.start + injection_offset(traffic_seed_, message.message_id, step_);
    const bool broadcast = message.destination == kBroadcast;
    metrics_.message_sent(broadcast);
    messages_[message.message_id] =
        SentMessage{message.source, message.destination, message.port, at, message.payload};
    // As SwarmNet's own application layer: a message to its own source is delivered at once.
    if (message.destination == message.source) {
      self_arrivals_.push_back({message.message_id, message.source, at.count(), 0});
      continue;
    }
    ns3engine::Message out;
    out.message_id = message.message_id;
    out.source = message.source;
    out.destination = broadcast ? ns3engine::kBroadcastNode : message.destination;
    out.port = message.port;
    out.inject_ns = at.count();
    out.payload.resize(message.payload.size());
    for (std::size_t i = 0; i < message.payload.size(); ++i) {
      out.payload[i] = static_cast<std::uint8_t>(message.payload[i]);
    }
    window_messages_.push_back(std::move(out));
  }
  const std::uint64_t events_before = network_->events();
  next_start_ = batch.start + step_;
  try {
    network_->run_window(next_start_.count(), xy_, window_messages_, arrivals_);
  } catch (const ns3engine::Interrupted& interrupted) {
    throw SimulationInterrupted(interrupted.what());
  }
  // Arrivals in time order, a self-delivery before ns-3's arrivals of the same instant.
  std::stable_sort(self_arrivals_.begin(), self_arrivals_.end(),
                   [](const auto& a, const auto& b) { return a.arrived_ns < b.arrived_ns; });
  ordered_.clear();
  std::merge(self_arrivals_.begin(), self_arrivals_.end(), arrivals_.begin(), arrivals_.end(),
             std::back_inserter(ordered_),
             [](const auto& a, const auto& b) { return a.arrived_ns < b.arrived_ns; });
  for (const auto& arrival : ordered_) deliver(arrival, result);
  forget_before(next_start_ - ApplicationLayer::kDuplicateWindow);
  result.events = network_->events() - events_before;
}

void Ns3NetworkEngine::deliver(const ns3engine::Arrival& arrival, StepResult& result) {
  const auto found = messages_.find(arrival.message_id);
  if (found == messages_.end()) {
    // Sent more than kDuplicateWindow ago and forgotten (as the native engine forgets it);
    // no ns-3 queue holds a packet that long with the scenario's mappings.
    ++late_arrivals_;
    return;
  }
  const SentMessage& message = found->second;
  const bool broadcast = message.destination == kBroadcast;
  // A unicast message is the destination's alone, as with the native engine's applications.
  if (!broadcast && arrival.receiver != message.destination) return;
  if (!delivered_.emplace(message.sent_at.count(), arrival.message_id, arrival.receiver).second) {
    metrics_.duplicate_suppressed();
    return;
  }
  const SimTime at{arrival.arrived_ns};
  if (broadcast) {
    metrics_.broadcast_delivered();
  } else {
    metrics_.unicast_delivered(at - message.sent_at, arrival.hops);
  }
  result.deliveries.push_back(Delivery{arrival.message_id, message.source, message.destination,
                                       arrival.receiver, message.sent_at, at, arrival.hops,
                                       message.port, message.payload});
}

// Messages sent before `horizon`, and the record of their deliveries, are forgotten: the memory
// stays bounded by what a window of kDuplicateWindow sends, as in the native application layer.
void Ns3NetworkEngine::forget_before(SimTime horizon) {
  for (auto it = messages_.begin(); it != messages_.end() && it->second.sent_at < horizon;) {
    it = messages_.erase(it);
  }
  delivered_.erase(delivered_.begin(), delivered_.lower_bound(std::make_tuple(
                                           horizon.count(), std::uint64_t{0}, RobotId{0})));
}

NetworkReport Ns3NetworkEngine::report() const {
  const ns3engine::Report counters = network_->report();
  const std::uint64_t undelivered = metrics_.unicast_sent() - metrics_.delivered();
  NetworkReport report = metrics_.report(undelivered, counters.events);
  report.mac = named_counts(counters.mac);
  report.routing = named_counts(counters.routing);
  // ns-3's ARP counts go where the native engine's are (summary.json's `arp`), under the names
  // they share with it; ns-3 reports its ARP drops as one figure (arp_drops).
  report.arp.clear();
  const auto arp_names = {std::pair{"arp_requests", "requests_sent"},
                          std::pair{"arp_replies", "replies_sent"},
                          std::pair{"arp_drops", "packets_dropped"}};
  for (const auto& [ns3_name, name] : arp_names) {
    const auto it =
        std::find_if(report.mac.begin(), report.mac.end(),
                     [ns3_name = ns3_name](const NamedCount& c) { return c.name == ns3_name; });
    if (it == report.mac.end()) continue;
    report.arp.push_back({name, it->value});
    report.mac.erase(it);
  }
  report.routing.push_back({"late_arrivals", late_arrivals_});
  report.dropped = named_counts(counters.drops);
  return report;
}

}  // namespace swarmnet
