// dcf80211's reports to routing (link_failed) on the SDK test kit: as ns-3.37's WifiMac
// DroppedMpdu trace, every drop of a unicast packet is reported (retry limit, full queue,
// expired wait) unless link_failure_reports: retry_limit; broadcasts never are.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "dcf80211.hpp"
#include "swarmnet/testing.hpp"

namespace swarmnet::dcf80211 {
namespace {

using testing::FakeMacContext;
using testing::PacketBuilder;
using testing::plugin_args;
using testing::TestScheduler;

class Dcf80211LinkFeedback : public ::testing::Test {
 protected:
  void make(std::int64_t queue_limit, double max_delay_s, const std::string& reports,
            const std::string& lifetime = "at_head") {
    mac_ = std::make_unique<Dcf80211>(plugin_args<Dcf80211>({{"queue_limit", queue_limit},
                                                             {"queue_max_delay_s", max_delay_s},
                                                             {"short_retry_limit", std::int64_t{1}},
                                                             {"link_failure_reports", reports},
                                                             {"mpdu_lifetime", lifetime}},
                                                            3, 0, 4));
    mac_->attach(node_);
  }
  static Packet packet(std::uint64_t uid, NodeId destination) {
    return PacketBuilder().uid(uid).from(0).to(destination).message(uid).payload_bytes(100).build();
  }
  [[nodiscard]] std::size_t drops(DropReason reason) const {
    std::size_t n = 0;
    for (const auto& d : node_.dropped) n += d.reason == reason ? 1 : 0;
    return n;
  }

  TestScheduler scheduler_;
  FakeMacContext node_{scheduler_, 0, 4};
  std::unique_ptr<Dcf80211> mac_;
};

TEST_F(Dcf80211LinkFeedback, AUnicastPacketRefusedByAFullQueueIsReported) {
  make(2, 0.5, "every_drop");
  mac_->enqueue(packet(1, 1), 1);  // being sent: it takes one of the two places
  mac_->enqueue(packet(2, 1), 1);  // fills the queue
  mac_->enqueue(packet(3, 2), 2);
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped[0].packet.uid, 3U);
  EXPECT_EQ(node_.dropped[0].reason, DropReason::queue_full);
  ASSERT_EQ(node_.link_failures.size(), 1U);
  EXPECT_EQ(node_.link_failures[0].packet.uid, 3U);
  EXPECT_EQ(node_.link_failures[0].next_hop, 2U);

  Packet broadcast = packet(4, kBroadcast);
  mac_->enqueue(broadcast, kBroadcast);  // a broadcast's drop matches no neighbour
  EXPECT_EQ(drops(DropReason::queue_full), 2U);
  EXPECT_EQ(node_.link_failures.size(), 1U);

  Packet arp = packet(5, 3);  // an ARP reply is reported like any unicast packet
  arp.message_id = kNoMessage;
  arp.payload.reset();
  arp.protocol = LinkProtocol::arp_reply;
  mac_->enqueue(arp, 3);
  ASSERT_EQ(node_.link_failures.size(), 2U);
  EXPECT_TRUE(node_.link_failures[1].packet.is_arp());
  EXPECT_EQ(node_.link_failures[1].next_hop, 3U);
}

TEST_F(Dcf80211LinkFeedback, RetryLimitModeReportsNoQueueDrop) {
  make(2, 0.5, "retry_limit");
  mac_->enqueue(packet(1, 1), 1);
  mac_->enqueue(packet(2, 1), 1);
  mac_->enqueue(packet(3, 2), 2);
  EXPECT_EQ(drops(DropReason::queue_full), 1U);
  EXPECT_TRUE(node_.link_failures.empty());
}

// ns-3.37 keeps an MPDU in its WifiMacQueue until its exchange ends: the packet on the air
// counts against the limit until it is acknowledged or dropped, then its place is free.
TEST_F(Dcf80211LinkFeedback, ThePacketOfAnExchangeUnderWayTakesAPlaceInTheQueue) {
  make(1, 0.5, "every_drop");
  mac_->enqueue(packet(1, 1), 1);
  scheduler_.run_for(from_seconds(0.001));
  ASSERT_EQ(node_.transmitted.size(), 1U);
  mac_->enqueue(packet(2, 2), 2);  // packet 1 is on the air: no place left
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped[0].packet.uid, 2U);
  EXPECT_EQ(node_.dropped[0].reason, DropReason::queue_full);
  mac_->on_transmit_end();
  scheduler_.run_for(from_seconds(0.001));  // no ACK: packet 1 dropped at the retry limit
  EXPECT_EQ(drops(DropReason::retry_limit), 1U);
  mac_->enqueue(packet(3, 3), 3);  // its place is free again
  EXPECT_EQ(drops(DropReason::queue_full), 1U);
  scheduler_.run_for(from_seconds(0.001));
  ASSERT_EQ(node_.transmitted.size(), 2U);
  EXPECT_EQ(node_.transmitted[1].frame.packet->uid, 3U);
}

// A broadcast gives its place up as it goes on the air, as ns-3 dequeues a group-addressed MPDU
// then: with a queue of one place, a packet handed down during its airtime is queued.
TEST_F(Dcf80211LinkFeedback, ABroadcastGivesItsPlaceUpAsItGoesOnTheAir) {
  make(1, 0.5, "every_drop");
  mac_->enqueue(packet(1, kBroadcast), kBroadcast);
  mac_->enqueue(packet(2, 1), 1);  // the broadcast waits for the medium: no place left
  EXPECT_EQ(drops(DropReason::queue_full), 1U);
  scheduler_.run_for(from_seconds(0.001));
  ASSERT_EQ(node_.transmitted.size(), 1U);  // the broadcast is on the air
  mac_->enqueue(packet(3, 1), 1);
  EXPECT_EQ(drops(DropReason::queue_full), 1U);
  mac_->on_transmit_end();
  scheduler_.run_for(from_seconds(0.001));
  ASSERT_EQ(node_.transmitted.size(), 2U);
  EXPECT_EQ(node_.transmitted[1].frame.packet->uid, 3U);
}

// Packet 1 is never acknowledged (retry limit 1) and ends after packet 2 has waited longer than
// queue_max_delay_s: both drops reach routing, in that order.
void run_retry_then_expiry(TestScheduler& scheduler, FakeMacContext& node, Dcf80211& mac) {
  mac.enqueue(PacketBuilder().uid(1).from(0).to(1).message(1).payload_bytes(100).build(), 1);
  mac.enqueue(PacketBuilder().uid(2).from(0).to(2).message(2).payload_bytes(100).build(), 2);
  scheduler.run_for(from_seconds(0.001));
  ASSERT_EQ(node.transmitted.size(), 1U);
  scheduler.run_for(from_seconds(0.002));  // the frame is still on the air, by the test's choice
  mac.on_transmit_end();
  scheduler.run_for(from_seconds(0.001));  // no ACK
}

TEST_F(Dcf80211LinkFeedback, RetryLimitAndExpiredWaitAreBothReported) {
  make(500, 0.002, "every_drop");
  run_retry_then_expiry(scheduler_, node_, *mac_);
  EXPECT_EQ(drops(DropReason::retry_limit), 1U);
  EXPECT_EQ(drops(DropReason::buffer_timeout), 1U);
  ASSERT_EQ(node_.link_failures.size(), 2U);
  EXPECT_EQ(node_.link_failures[0].packet.uid, 1U);
  EXPECT_EQ(node_.link_failures[0].next_hop, 1U);
  EXPECT_EQ(node_.link_failures[1].packet.uid, 2U);
  EXPECT_EQ(node_.link_failures[1].next_hop, 2U);
}

TEST_F(Dcf80211LinkFeedback, RetryLimitModeReportsOnlyTheRetryLimit) {
  make(500, 0.002, "retry_limit");
  run_retry_then_expiry(scheduler_, node_, *mac_);
  EXPECT_EQ(drops(DropReason::buffer_timeout), 1U);
  ASSERT_EQ(node_.link_failures.size(), 1U);
  EXPECT_EQ(node_.link_failures[0].packet.uid, 1U);
}

// ns-3's WifiMacQueue::Insert: a packet arriving at a full queue first has the expired packets
// removed (Expired, reported), and is queued if that made room. With mpdu_lifetime: at_head the
// packet on the air keeps its place.
TEST_F(Dcf80211LinkFeedback, AFullQueueDropsItsExpiredPacketsBeforeRefusingOne) {
  make(2, 0.001, "every_drop", "at_head");
  mac_->enqueue(packet(1, 1), 1);
  mac_->enqueue(packet(2, 2), 2);
  scheduler_.run_for(from_seconds(0.002));  // packet 1 on the air, packet 2 expired in the queue
  mac_->enqueue(packet(3, 3), 3);
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped[0].packet.uid, 2U);
  EXPECT_EQ(node_.dropped[0].reason, DropReason::buffer_timeout);
  ASSERT_EQ(node_.link_failures.size(), 1U);
  EXPECT_EQ(node_.link_failures[0].next_hop, 2U);
  mac_->enqueue(packet(4, 3), 3);  // packet 3 is fresh: now the queue is full
  EXPECT_EQ(drops(DropReason::queue_full), 1U);
}

// With mpdu_lifetime: ns3 the packet on the air expires too: both places are freed.
TEST_F(Dcf80211LinkFeedback, AnArrivalWipesThePacketOnTheAirWhenItsLifetimeEnded) {
  make(2, 0.001, "every_drop", "ns3");
  mac_->enqueue(packet(1, 1), 1);
  mac_->enqueue(packet(2, 2), 2);
  scheduler_.run_for(from_seconds(0.002));  // packet 1 on the air, both outlived 1 ms
  mac_->enqueue(packet(3, 3), 3);
  ASSERT_EQ(node_.dropped.size(), 2U);
  EXPECT_EQ(node_.dropped[0].packet.uid, 1U);
  EXPECT_EQ(node_.dropped[1].packet.uid, 2U);
  EXPECT_EQ(drops(DropReason::buffer_timeout), 2U);
  ASSERT_EQ(node_.link_failures.size(), 2U);
  EXPECT_EQ(node_.link_failures[0].next_hop, 1U);
  EXPECT_EQ(node_.link_failures[1].next_hop, 2U);
  mac_->enqueue(packet(4, 3), 3);  // packets 3 and 4 fill the queue
  mac_->enqueue(packet(5, 3), 3);
  EXPECT_EQ(drops(DropReason::queue_full), 1U);
  EXPECT_EQ(node_.dropped.back().packet.uid, 5U);
}

}  // namespace
}  // namespace swarmnet::dcf80211
