// AODV control messages that name nodes outside the network (ids 0..9 here). The route table is
// indexed by node id, so a message that names another id where a route would be made (a RREQ's
// originator, a RREP's destination or originator, the datagram's source) is corrupt: it is
// counted as malformed and dropped before any route is touched. A RREQ may still ask for a
// destination that does not exist; nobody answers it, and it is relayed as any other.
#include <gtest/gtest.h>

#include <cstdint>

#include "aodv_one_node.hpp"

namespace swarmnet::aodv {
namespace {

// Far beyond the network, below kNoNode: a table sized by it would take gigabytes.
constexpr NodeId kForeign = 4'000'000'000U;

class AodvForeignIds : public AodvOneNode {
 protected:
  [[nodiscard]] static Rreq request(NodeId originator, NodeId destination) {
    Rreq rreq;
    rreq.originator = originator;
    rreq.originator_seq = 1;
    rreq.id = 1;
    rreq.destination = destination;
    rreq.unknown_seq = true;
    rreq.ttl = 2;
    return rreq;
  }
};

TEST_F(AodvForeignIds, ARreqFromAnOriginatorOutsideTheNetworkIsMalformed) {
  make();
  hear(request(kForeign, 3), 5);
  EXPECT_EQ(node_.counter("malformed"), 1U);
  EXPECT_EQ(aodv_->routing_table().entry(kForeign), nullptr);
  EXPECT_EQ(aodv_->routing_table().entry(5), nullptr);  // not even the sender's route
  EXPECT_EQ(aodv_->routing_table().size(), 0U);
  scheduler_.run_for(from_seconds(0.05));
  EXPECT_EQ(node_.counter("control_rreq"), 0U);  // not relayed
}

TEST_F(AodvForeignIds, ARrepToADestinationOutsideTheNetworkIsMalformed) {
  make();
  Rrep rrep;
  rrep.destination = kForeign;
  rrep.destination_seq = 1;
  rrep.originator = 0;
  rrep.lifetime_ms = 2000;
  hear(rrep, 5);
  EXPECT_EQ(node_.counter("malformed"), 1U);
  EXPECT_EQ(aodv_->routing_table().entry(kForeign), nullptr);
  EXPECT_EQ(aodv_->routing_table().size(), 0U);

  // A RREP for 5 answering a RREQ of a node that does not exist: corrupt, so not even the
  // route to 5 is made.
  hear(Rrep{.destination = 5, .destination_seq = 1, .originator = kForeign}, 5);
  EXPECT_EQ(node_.counter("malformed"), 2U);
  EXPECT_EQ(aodv_->routing_table().size(), 0U);
}

TEST_F(AodvForeignIds, AMessageWhoseDatagramSourceIsOutsideTheNetworkIsMalformed) {
  // With control_via_route_to_neighbor (ns-3's IP) the sender is the datagram's source, which
  // would become a one-hop route.
  make(testing::ParamOverrides{{"control_via_route_to_neighbor", true}});
  Packet packet = testing::PacketBuilder().uid(1).from(kForeign).to(kBroadcast).hops(1).build();
  encode(request(7, 3), packet.header);
  aodv_->receive(std::move(packet), 5);
  EXPECT_EQ(node_.counter("malformed"), 1U);
  EXPECT_EQ(aodv_->routing_table().entry(kForeign), nullptr);
  EXPECT_EQ(aodv_->routing_table().size(), 0U);
}

TEST_F(AodvForeignIds, ARreqForADestinationOutsideTheNetworkIsRelayed) {
  make();
  hear(request(7, 12), 5);
  EXPECT_EQ(node_.counter("malformed"), 0U);
  EXPECT_NE(aodv_->routing_table().entry(7), nullptr);  // the reverse route
  scheduler_.run_for(from_seconds(0.05));
  EXPECT_EQ(node_.counter("control_rreq"), 1U);
}

}  // namespace
}  // namespace swarmnet::aodv
