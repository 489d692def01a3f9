// SDK test kit: fake contexts for a routing or MAC plugin under test. Each records what the
// plugin asked of the kernel (frames, packets, drops, counters) for the test to inspect, and
// runs timers on a TestScheduler that the test drives.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "swarmnet/mac.hpp"
#include "swarmnet/routing.hpp"
#include "swarmnet/testing/test_scheduler.hpp"

namespace swarmnet::testing {

// The NodeContext part both fakes share.
template <typename Context>
class FakeNode : public Context {
 public:
  FakeNode(TestScheduler& scheduler, NodeId node, std::size_t node_count)
      : scheduler_(scheduler), node_(node), node_count_(node_count) {}

  Vec2 where = Vec2::Zero();                                   // what position() returns
  std::map<std::string, std::uint64_t, std::less<>> counters;  // what count() added up

  [[nodiscard]] NodeId node() const override { return node_; }
  [[nodiscard]] std::size_t node_count() const override { return node_count_; }
  [[nodiscard]] SimTime now() const override { return scheduler_.now(); }
  [[nodiscard]] Vec2 position() const override { return where; }
  TimerId schedule(SimTime delay, std::function<void()> callback) override {
    return scheduler_.schedule(delay, std::move(callback));
  }
  void cancel(TimerId timer) override { scheduler_.cancel(timer); }
  void count(std::string_view counter, std::uint64_t amount = 1) override {
    auto it = counters.find(counter);
    if (it == counters.end()) it = counters.emplace(std::string(counter), 0).first;
    it->second += amount;
  }
  // A counter's total, 0 when never counted.
  [[nodiscard]] std::uint64_t counter(std::string_view name) const {
    const auto it = counters.find(name);
    return it == counters.end() ? 0 : it->second;
  }

 private:
  TestScheduler& scheduler_;
  NodeId node_;
  std::size_t node_count_;
};

struct Dropped {
  Packet packet;
  DropReason reason;
};

// What a routing plugin sees of its node.
class FakeRoutingContext final : public FakeNode<RoutingContext> {
 public:
  using FakeNode::FakeNode;

  struct ToMac {
    Packet packet;
    NodeId next_hop;
    SimTime at;
  };
  std::vector<ToMac> to_mac;           // send_to_mac() calls, in order
  std::vector<Packet> delivered;       // deliver() calls
  std::vector<Dropped> dropped;        // drop() calls
  std::vector<Packet> forwarded;       // trace_forward() calls
  std::uint64_t next_uid = 1'000'000;  // uids of control packets made here

  Packet make_control_packet(NodeId destination) override {
    Packet packet;
    packet.uid = next_uid++;
    packet.source = node();
    packet.destination = destination;
    packet.sent_at = now();
    return packet;
  }
  void send_to_mac(Packet packet, NodeId next_hop) override {
    to_mac.push_back({std::move(packet), next_hop, now()});
  }
  void deliver(const Packet& packet) override { delivered.push_back(packet); }
  void drop(const Packet& packet, DropReason reason) override {
    dropped.push_back({packet, reason});
  }
  void trace_forward(const Packet& packet) override { forwarded.push_back(packet); }
  [[nodiscard]] bool link_address_known(NodeId neighbor) const override {
    return unresolved.count(neighbor) == 0;
  }
  std::set<NodeId> unresolved;  // neighbours link_address_known() denies (default: none)
};

// What a MAC plugin sees of its node and PHY. The test sets `busy` and calls the MAC's
// on_transmit_end() / on_receive() itself, as the kernel's PHY would.
class FakeMacContext final : public FakeNode<MacContext> {
 public:
  using FakeNode::FakeNode;

  struct Transmission {
    Frame frame;
    SimTime at;
    SimTime duration;
  };
  bool busy = false;                      // what medium_busy() returns
  std::vector<Transmission> transmitted;  // transmit() calls
  struct Up {
    Packet packet;
    NodeId from;
  };
  std::vector<Up> delivered;  // deliver() calls
  struct Failure {
    Packet packet;
    NodeId next_hop;
  };
  std::vector<Failure> link_failures;  // link_failed() calls
  std::vector<Dropped> dropped;        // drop() calls
  struct Acknowledgement {
    Packet packet;
    NodeId next_hop;
    std::uint32_t attempts;
  };
  std::vector<Acknowledgement> acknowledgements;  // acknowledged() calls
  std::vector<Acknowledgement> given_up;          // gave_up() calls
  std::uint64_t next_frame_uid = 1;

  void transmit(Frame frame, SimTime duration) override {
    frame.uid = next_frame_uid++;
    frame.transmitter = node();
    transmitted.push_back({std::move(frame), now(), duration});
  }
  [[nodiscard]] bool medium_busy() const override { return busy; }
  void deliver(Packet packet, NodeId from) override {
    delivered.push_back({std::move(packet), from});
  }
  void link_failed(const Packet& packet, NodeId next_hop) override {
    link_failures.push_back({packet, next_hop});
  }
  void drop(const Packet& packet, DropReason reason) override {
    dropped.push_back({packet, reason});
  }
  void acknowledged(const Packet& packet, NodeId next_hop, std::uint32_t attempts) override {
    acknowledgements.push_back({packet, next_hop, attempts});
  }
  void gave_up(const Packet& packet, NodeId next_hop, std::uint32_t attempts) override {
    given_up.push_back({packet, next_hop, attempts});
  }
};

}  // namespace swarmnet::testing
