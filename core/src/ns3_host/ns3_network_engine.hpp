// The network half with ns-3.37 as its engine (`network.engine: ns3`, docs/ns3-engine.md): the
// step protocol's batches go to an ns-3 network in the engine module, its arrivals come back as
// deliveries. What the robots see is decided here, as SwarmNet's own engine decides it: messages
// taken in at the same instants (injection_offset), a message to its own source delivered at
// once, each delivered once per receiver (later copies counted as duplicates, forgotten after
// ApplicationLayer::kDuplicateWindow), and the same metrics (network/network_metrics.hpp).
#pragma once

#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <vector>

#include "network/network_engine.hpp"
#include "network/network_metrics.hpp"
#include "network/network_settings.hpp"
#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet {

class Ns3NetworkEngine final : public NetworkEngine {
 public:
  // Loads the module and sets ns-3 up; throws std::runtime_error (module) or
  // std::invalid_argument (settings) saying why not.
  // `stop_requested`, when given, is asked every millisecond of simulated time inside a window
  // (ns3engine::Config::stop_requested); a true answer throws SimulationInterrupted.
  explicit Ns3NetworkEngine(const NetworkSettings& settings, bool (*stop_requested)() = nullptr);

  void run_step(const StepBatch& batch, StepResult& result) override;
  [[nodiscard]] NetworkReport report() const override;
  void finish() override {}

 private:
  // What a delivery repeats of its message.
  struct SentMessage {
    RobotId source = kNoNode;
    RobotId destination = kBroadcast;
    std::uint16_t port = 0;
    SimTime sent_at{};
    Payload payload;
  };

  void check_batch(const StepBatch& batch) const;
  void deliver(const ns3engine::Arrival& arrival, StepResult& result);
  void forget_before(SimTime horizon);

  std::uint64_t traffic_seed_;  // places injections in their step (NetworkSettings)
  SimTime step_;
  std::uint32_t nodes_;
  SimTime next_start_{};
  std::unique_ptr<ns3engine::Network> network_;
  NetworkMetrics metrics_;
  // By message id. Ids ascend in send order and a step's messages are sent within the step, so
  // the map's order is the order of sent_at up to one step: forget_before() relies on it.
  std::map<std::uint64_t, SentMessage> messages_;
  std::set<std::tuple<std::int64_t, std::uint64_t, RobotId>> delivered_;  // sent_at, id, receiver
  std::uint64_t late_arrivals_ = 0;  // arrivals of messages already forgotten
  // Buffers reused across steps.
  std::vector<double> xy_;
  std::vector<ns3engine::Message> window_messages_;
  std::vector<ns3engine::Arrival> arrivals_;
  std::vector<ns3engine::Arrival> self_arrivals_;
  std::vector<ns3engine::Arrival> ordered_;  // both, merged in time order
};

}  // namespace swarmnet
