// AODV headers that name nodes outside the network (ids 0..9 here). The route table is indexed
// by node id, so a header that would make a route to another id is corrupt: it is counted as
// malformed and dropped before any route is touched. A RREQ may still ask for a destination
// that does not exist; nobody answers it, and it is relayed as any other.
#include <gtest/gtest.h>

#include <cstdint>

#include "aodv_one_node.hpp"

namespace swarmnet::aodv {
namespace {

// Far beyond the network, below kNoNode: a table sized by it would take gigabytes.
constexpr NodeId kForeign = 4'000'000'000U;

class AodvForeignIds : public AodvOneNode {
 protected:
  void SetUp() override { make(); }
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
  hear(request(kForeign, 3), 5);
  EXPECT_EQ(node_.counter("malformed"), 1U);
  EXPECT_EQ(aodv_->routing_table().entry(kForeign), nullptr);
  EXPECT_EQ(aodv_->routing_table().entry(5), nullptr);  // not even the sender's route
  EXPECT_EQ(aodv_->routing_table().size(), 0U);
  scheduler_.run_for(from_seconds(0.05));
  EXPECT_EQ(node_.counter("control_rreq"), 0U);  // not relayed
}

TEST_F(AodvForeignIds, ARrepToADestinationOutsideTheNetworkIsMalformed) {
  Rrep rrep;
  rrep.destination = kForeign;
  rrep.destination_seq = 1;
  rrep.originator = 0;
  rrep.lifetime_ms = 2000;
  hear(rrep, 5);
  EXPECT_EQ(node_.counter("malformed"), 1U);
  EXPECT_EQ(aodv_->routing_table().entry(kForeign), nullptr);
  EXPECT_EQ(aodv_->routing_table().size(), 0U);

  // A RREP for 5 answering a RREQ of a node that does not exist.
  hear(Rrep{.destination = 5, .destination_seq = 1, .originator = kForeign}, 5);
  EXPECT_EQ(node_.counter("malformed"), 2U);
}

TEST_F(AodvForeignIds, ARreqForADestinationOutsideTheNetworkIsRelayed) {
  hear(request(7, 12), 5);
  EXPECT_EQ(node_.counter("malformed"), 0U);
  EXPECT_NE(aodv_->routing_table().entry(7), nullptr);  // the reverse route
  EXPECT_EQ(aodv_->routing_table().entry(12), nullptr);
  scheduler_.run_for(from_seconds(0.05));
  EXPECT_EQ(node_.counter("control_rreq"), 1U);
}

}  // namespace
}  // namespace swarmnet::aodv
