// The ns-3 network: nodes with YansWifi ad hoc devices, IPv4 with ARP, the routing the Config
// names, one endpoint per node for the robots' messages, and the counters, driven window by
// window by the kernel (ns3_engine_api.hpp).
#pragma once

#include <ns3/mobility-model.h>
#include <ns3/node-container.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "ns3_engine/live_endpoints.hpp"
#include "ns3_engine/ns3_counters.hpp"
#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet::ns3engine {

class Ns3Network final : public Network {
 public:
  // Checks all of `config` before ns-3 sees any of it, then builds the network (time 0). Throws
  // std::runtime_error naming what it cannot apply, or if another network exists (ns-3's
  // simulator is one per process).
  explicit Ns3Network(const Config& config);
  ~Ns3Network() override;
  Ns3Network(const Ns3Network&) = delete;
  Ns3Network& operator=(const Ns3Network&) = delete;
  Ns3Network(Ns3Network&&) = delete;
  Ns3Network& operator=(Ns3Network&&) = delete;

  void run_window(std::int64_t end_ns, const std::vector<double>& xy,
                  const std::vector<Message>& messages, std::vector<Arrival>& arrivals) override;

  [[nodiscard]] Report report() const override;
  [[nodiscard]] std::uint64_t events() const override;

 private:
  void build(const Config& config);
  void check_window(std::int64_t end_ns, const std::vector<double>& xy,
                    const std::vector<Message>& messages) const;
  // Runs every event before `end_ns`, and none at or after it.
  void run_until(std::int64_t end_ns);

  std::uint32_t node_count_ = 0;
  ns3::NodeContainer nodes_;
  std::vector<ns3::Ptr<ns3::MobilityModel>> mobility_;
  CounterSinks counters_;
  EndpointWorld world_;
  std::vector<std::unique_ptr<Endpoint>> endpoints_;
  std::int64_t now_ns_ = 0;             // where the next window starts
  std::uint64_t stop_events_ = 0;       // the engine's own Stop events, not counted in the report
  bool (*stop_requested_)() = nullptr;  // Config::stop_requested
};

}  // namespace swarmnet::ns3engine
