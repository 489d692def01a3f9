// One AODV instance on the SDK test kit, as the protocol-rule tests drive it: node 0 of 10 with a
// fake routing context, messages heard from neighbours, and HELLOs.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <utility>
#include <variant>

#include "aodv.hpp"
#include "swarmnet/testing.hpp"

namespace swarmnet::aodv {

class AodvOneNode : public ::testing::Test {
 protected:
  void make(const testing::ParamOverrides& overrides = {}) {
    aodv_ = std::make_unique<Aodv>(testing::plugin_args<Aodv>(overrides, 5, 0, 10));
    aodv_->attach(node_);
  }
  // `message` arrives in a broadcast frame from neighbour `from`.
  void hear(const Message& message, NodeId from) {
    Packet packet =
        testing::PacketBuilder().uid(next_uid_++).from(from).to(kBroadcast).hops(1).build();
    std::visit([&packet](const auto& m) { encode(m, packet.header); }, message);
    aodv_->receive(std::move(packet), from);
  }
  void hello_from(NodeId neighbor, std::uint32_t seq = 1) {
    Rrep hello;
    hello.destination = neighbor;
    hello.originator = neighbor;
    hello.destination_seq = seq;
    hello.lifetime_ms = 2000;
    hear(hello, neighbor);
  }

  testing::TestScheduler scheduler_;
  testing::FakeRoutingContext node_{scheduler_, 0, 10};
  std::unique_ptr<Aodv> aodv_;
  std::uint64_t next_uid_ = 1;
};

}  // namespace swarmnet::aodv
