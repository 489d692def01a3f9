#include "ns3_host/ns3_network_engine.hpp"

#include <stdexcept>
#include <string>

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

Ns3NetworkEngine::Ns3NetworkEngine(const NetworkSettings& settings)
    : seed_(settings.seed),
      step_(from_seconds(settings.step_s)),
      nodes_(settings.nodes),
      network_(create_ns3_network(ns3_config_for(settings))) {}

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
  for (const auto& message : batch.messages) {
    const SimTime at = batch.start + injection_offset(seed_, message.message_id, step_);
    const bool broadcast = message.destination == kBroadcast;
    metrics_.message_sent(broadcast);
    messages_[message.message_id] =
        SentMessage{message.source, message.destination, message.port, at, message.payload};
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
  const std::uint64_t events_before = network_->report().events;
  arrivals_.clear();
  next_start_ = batch.start + step_;
  network_->run_window(next_start_.count(), xy_, window_messages_, arrivals_);
  for (const auto& arrival : arrivals_) deliver(arrival, result);
  result.events = network_->report().events - events_before;
}

void Ns3NetworkEngine::deliver(const ns3engine::Arrival& arrival, StepResult& result) {
  const auto found = messages_.find(arrival.message_id);
  if (found == messages_.end()) {
    throw std::runtime_error("ns-3 engine: an arrival of message " +
                             std::to_string(arrival.message_id) + ", which was never sent");
  }
  const SentMessage& message = found->second;
  const bool broadcast = message.destination == kBroadcast;
  // A unicast message is the destination's alone, as with the native engine's applications.
  if (!broadcast && arrival.receiver != message.destination) return;
  if (!delivered_.emplace(arrival.message_id, arrival.receiver).second) {
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

NetworkReport Ns3NetworkEngine::report() const {
  const ns3engine::Report counters = network_->report();
  const std::uint64_t in_flight = metrics_.unicast_sent() - metrics_.delivered();
  NetworkReport report = metrics_.report(in_flight, counters.events);
  report.mac = named_counts(counters.mac);
  report.routing = named_counts(counters.routing);
  report.dropped = named_counts(counters.drops);
  return report;
}

}  // namespace swarmnet
