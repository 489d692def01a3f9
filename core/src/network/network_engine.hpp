// What the network half's loop drives (coupling/network_half.cpp): SwarmNet's own simulator or
// ns-3 (ns3_host/ns3_network_engine.hpp), chosen by `network.engine`. Both take the step
// protocol's batches and give its results, so everything above them is the same for either.
#pragma once

#include "protocol/network_report.hpp"
#include "protocol/step_data.hpp"

namespace swarmnet {

class NetworkEngine {
 public:
  NetworkEngine() = default;
  NetworkEngine(const NetworkEngine&) = delete;
  NetworkEngine& operator=(const NetworkEngine&) = delete;
  NetworkEngine(NetworkEngine&&) = delete;
  NetworkEngine& operator=(NetworkEngine&&) = delete;
  virtual ~NetworkEngine() = default;

  // Simulates [batch.start, batch.start + step) and fills `result` (NetworkSimulator::run_step
  // states the contract in full).
  virtual void run_step(const StepBatch& batch, StepResult& result) = 0;
  // Metrics so far (network/network_metrics.hpp defines every field).
  [[nodiscard]] virtual NetworkReport report() const = 0;
  // Flushes what the engine writes; call once, at the end.
  virtual void finish() = 0;
};

}  // namespace swarmnet
