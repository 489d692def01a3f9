// A small stand-alone network for testing the AODV protocol class directly (its sources are
// compiled into the test), so that tests can read every node's route table at any instant.
//
// Nodes sit at positions the test sets (and may change at any time); a frame reaches every node
// within `range_m` of the sender at the end of its airtime, unless the test blocked that directed
// link. Each node's MAC sends one frame at a time in FIFO order, airtime
// (28 + packet bytes) * 8 / 6 Mbit/s. With `mac_feedback`, a unicast frame its next hop cannot
// hear is reported to routing through link_failed() (an acknowledging MAC after its retries),
// otherwise it is lost silently (like ideal_mac). Events run on the kernel's scheduler.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "aodv.hpp"
#include "network/scheduler.hpp"
#include "swarmnet/params.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet::aodv::test {

struct TestDelivery {
  NodeId receiver = kNoNode;
  NodeId source = kNoNode;
  std::uint64_t message_id = 0;
  std::uint32_t hops = 0;
  SimTime sent_at{};
  SimTime delivered_at{};
};

struct TestDrop {
  NodeId node = kNoNode;
  std::uint64_t message_id = 0;
  bool control = false;
  DropReason reason = DropReason::no_route;
};

struct Reception {
  NodeId receiver = kNoNode;
  NodeId from = kNoNode;
  SimTime at{};
  std::vector<std::uint8_t> header;  // control packets only
};

// AODV's default parameters with `overrides` applied.
ParamSet aodv_params(const std::map<std::string, ParamValue>& overrides = {});

class TestNetwork {
 public:
  TestNetwork(std::vector<Vec2> positions, const ParamSet& params, bool mac_feedback,
              std::uint64_t seed = 1, double range_m = 120.0);
  TestNetwork(const TestNetwork&) = delete;
  TestNetwork& operator=(const TestNetwork&) = delete;
  TestNetwork(TestNetwork&&) = delete;
  TestNetwork& operator=(TestNetwork&&) = delete;
  ~TestNetwork();

  [[nodiscard]] std::size_t size() const { return nodes_.size(); }
  [[nodiscard]] SimTime now() const { return scheduler_.now(); }
  void move(NodeId node, Vec2 position) { positions_[node] = position; }
  [[nodiscard]] const std::vector<Vec2>& positions() const { return positions_; }
  void block(NodeId from, NodeId to) { blocked_.insert({from, to}); }

  // The application of `source` sends message `message_id` (100-byte payload) now.
  void send(NodeId source, NodeId destination, std::uint64_t message_id);
  // Hands `node` a control message as if `from` had sent it (bypasses the radio).
  void inject(NodeId node, const Message& message, NodeId from);
  void run_until(SimTime end) { scheduler_.run_until(end); }
  void run_for(SimTime duration) { scheduler_.run_until(now() + duration); }

  [[nodiscard]] Aodv& aodv(NodeId node);
  [[nodiscard]] const std::vector<TestDelivery>& deliveries() const { return deliveries_; }
  [[nodiscard]] const std::vector<TestDrop>& drops() const { return drops_; }
  [[nodiscard]] const std::vector<Reception>& receptions() const { return receptions_; }
  // A routing counter of one node, or summed over all nodes.
  [[nodiscard]] std::uint64_t count(NodeId node, const std::string& counter) const;
  [[nodiscard]] std::uint64_t count(const std::string& counter) const;
  // The valid route of `node` to `destination` at now(), or null.
  [[nodiscard]] const RouteEntry* valid_route(NodeId node, NodeId destination) const;
  // The first routing loop in the union of valid routes at now(), described, or "" if none.
  [[nodiscard]] std::string find_loop() const;
  [[nodiscard]] bool in_range(NodeId a, NodeId b) const;

 private:
  struct TestNode;
  void transmit(NodeId sender, Packet packet, NodeId next_hop);
  void deliver(NodeId node, const Packet& packet);

  Scheduler scheduler_;
  std::vector<Vec2> positions_;
  bool mac_feedback_;
  double range_m_;
  std::set<std::pair<NodeId, NodeId>> blocked_;
  std::vector<std::unique_ptr<TestNode>> nodes_;
  std::vector<SimTime> busy_until_;
  std::uint64_t next_uid_ = 1;
  std::vector<TestDelivery> deliveries_;
  std::vector<TestDrop> drops_;
  std::vector<Reception> receptions_;
};

}  // namespace swarmnet::aodv::test
