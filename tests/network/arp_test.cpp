// ARP as ns-3.37 runs it (network/arp.hpp): a miss sends one request and queues, the reply
// drains the queue in order, the fourth packet during a miss is dropped, retries come at the
// cache's one-second ticks and the entry dies after three, entries expire on ns-3's timeouts.
#include "network/arp.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "network/network_metrics.hpp"
#include "network/packet_uid_source.hpp"
#include "network/scheduler.hpp"

namespace swarmnet {
namespace {

constexpr NodeId kSelf = 0;
constexpr NodeId kNeighbor = 1;

// Stands for the node below ARP: records what reaches the MAC and what is dropped.
struct RecordingLink final : Arp::Link {
  struct Sent {
    Packet packet;
    NodeId next_hop;
    SimTime at;
  };
  explicit RecordingLink(Scheduler& scheduler) : scheduler(scheduler) {}
  Packet make_packet(NodeId destination) override {
    Packet packet;
    packet.uid = uids.take();
    packet.source = kSelf;
    packet.destination = destination;
    packet.sent_at = scheduler.now();
    return packet;
  }
  void send_to_mac(Packet packet, NodeId next_hop) override {
    sent.push_back({std::move(packet), next_hop, scheduler.now()});
  }
  void drop(const Packet& packet, DropReason reason) override {
    dropped.emplace_back(packet.uid, reason);
  }
  [[nodiscard]] std::size_t requests() const {
    std::size_t n = 0;
    for (const Sent& s : sent) n += s.packet.protocol == LinkProtocol::arp_request ? 1 : 0;
    return n;
  }
  Scheduler& scheduler;
  PacketUidSource uids;
  std::vector<Sent> sent;
  std::vector<std::pair<std::uint64_t, DropReason>> dropped;
};

class ArpTest : public ::testing::Test {
 protected:
  ArpTest() : link_(scheduler_), arp_(kSelf, ArpTimings{}, scheduler_, metrics_, 7, link_) {}

  static Packet data(std::uint64_t uid) {
    Packet packet;
    packet.uid = uid;
    packet.source = kSelf;
    packet.destination = 5;
    packet.message_id = uid;
    return packet;
  }
  static Packet reply_from(NodeId neighbor) {
    Packet packet;
    packet.source = neighbor;
    packet.destination = kSelf;
    packet.protocol = LinkProtocol::arp_reply;
    return packet;
  }
  void at(double seconds, std::function<void()> action) {
    scheduler_.schedule_at(from_seconds(seconds), std::move(action));
  }
  std::uint64_t arp_counter(const char* name) const {
    for (const NamedCount& c : metrics_.report(0, 0).arp) {
      if (c.name == name) return c.value;
    }
    return 0;
  }

  Scheduler scheduler_;
  NetworkMetrics metrics_;
  RecordingLink link_;
  Arp arp_;
};

TEST_F(ArpTest, AMissSendsOneJitteredRequestAndQueuesThePacket) {
  at(0.0, [this] { arp_.send(data(100), kNeighbor); });
  at(0.0, [this] { arp_.send(data(101), kNeighbor); });  // joins the queue: no second request
  scheduler_.run_until(from_seconds(0.5));
  ASSERT_EQ(link_.sent.size(), 1U);
  const RecordingLink::Sent& request = link_.sent[0];
  EXPECT_EQ(request.packet.protocol, LinkProtocol::arp_request);
  EXPECT_EQ(request.next_hop, kBroadcast);
  EXPECT_EQ(request.packet.source, kSelf);
  EXPECT_EQ(request.packet.destination, kNeighbor);
  EXPECT_EQ(request.packet.size_bytes(), 28U);  // an ARP header for Ethernet and IPv4
  // ns-3's RequestJitter: a uniform draw below 10 ms, truncated to whole milliseconds.
  EXPECT_LT(request.at, from_seconds(0.010));
  EXPECT_EQ(request.at.count() % 1'000'000, 0);
  EXPECT_FALSE(arp_.resolved(kNeighbor));
  EXPECT_EQ(arp_counter("requests_sent"), 1U);
}

TEST_F(ArpTest, TheReplyDrainsTheQueueInOrder) {
  at(0.0, [this] {
    for (std::uint64_t uid = 100; uid < 103; ++uid) arp_.send(data(uid), kNeighbor);
  });
  at(0.2, [this] { arp_.receive(reply_from(kNeighbor)); });
  at(0.3, [this] { arp_.send(data(103), kNeighbor); });  // resolved now: straight to the MAC
  scheduler_.run_until(from_seconds(1.0));
  ASSERT_EQ(link_.sent.size(), 5U);  // the request, three released packets, one sent at once
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(link_.sent[i].packet.uid, 99 + i);
    EXPECT_EQ(link_.sent[i].next_hop, kNeighbor);
    EXPECT_EQ(link_.sent[i].at, from_seconds(0.2));
  }
  EXPECT_EQ(link_.sent[4].packet.uid, 103U);
  EXPECT_EQ(link_.sent[4].at, from_seconds(0.3));
  EXPECT_TRUE(arp_.resolved(kNeighbor));
  EXPECT_TRUE(link_.dropped.empty());
  EXPECT_EQ(arp_counter("resolved"), 1U);
}

TEST_F(ArpTest, TheFourthPacketDuringAMissIsDroppedAndCounted) {
  at(0.0, [this] {
    for (std::uint64_t uid = 100; uid < 105; ++uid) arp_.send(data(uid), kNeighbor);
  });
  at(0.5, [this] { arp_.receive(reply_from(kNeighbor)); });
  scheduler_.run_until(from_seconds(1.0));
  ASSERT_EQ(link_.dropped.size(), 2U);
  EXPECT_EQ(link_.dropped[0], std::make_pair(std::uint64_t{103}, DropReason::arp_queue_full));
  EXPECT_EQ(link_.dropped[1], std::make_pair(std::uint64_t{104}, DropReason::arp_queue_full));
  EXPECT_EQ(link_.sent.size(), 4U);  // the request and the three queued packets
}

TEST_F(ArpTest, RetriesComeAtTheTicksAndTheEntryDiesAfterThree) {
  at(0.0, [this] { arp_.send(data(100), kNeighbor); });
  scheduler_.run_until(from_seconds(10.0));
  // The first request, then one retry at each tick of the cache's timer (1, 2, 3 s); the
  // tick at 4 s finds no retry left: the entry dies and its packet is dropped.
  ASSERT_EQ(link_.requests(), 4U);
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(link_.sent[i].at, from_seconds(1.0 * i));
  ASSERT_EQ(link_.dropped.size(), 1U);
  EXPECT_EQ(link_.dropped[0], std::make_pair(std::uint64_t{100}, DropReason::arp_unresolved));
  EXPECT_EQ(arp_counter("failed"), 1U);
  EXPECT_EQ(arp_counter("requests_sent"), 4U);
}

TEST_F(ArpTest, ADeadNeighbourDropsPacketsUntilTheDeadTimeoutThenAsksAgain) {
  at(0.0, [this] { arp_.send(data(100), kNeighbor); });    // dies at 4 s
  at(50.0, [this] { arp_.send(data(101), kNeighbor); });   // dead: dropped at once
  at(104.5, [this] { arp_.send(data(102), kNeighbor); });  // 100.5 s after death: asks again
  scheduler_.run_until(from_seconds(104.6));
  ASSERT_EQ(link_.dropped.size(), 2U);
  EXPECT_EQ(link_.dropped[1], std::make_pair(std::uint64_t{101}, DropReason::arp_unresolved));
  EXPECT_EQ(link_.requests(), 5U);
  EXPECT_GE(link_.sent.back().at, from_seconds(104.5));
}

TEST_F(ArpTest, OneTimerServesTheWholeCache) {
  at(0.0, [this] { arp_.send(data(100), 1); });
  at(0.6, [this] { arp_.send(data(101), 2); });  // waits 0.4 s to its first retry, as in ns-3
  scheduler_.run_until(from_seconds(1.5));
  std::vector<std::pair<NodeId, SimTime>> retries;
  for (const RecordingLink::Sent& s : link_.sent) {
    if (s.at == from_seconds(1.0)) retries.emplace_back(s.packet.destination, s.at);
  }
  ASSERT_EQ(retries.size(), 2U);  // both retried at the tick, in address order
  EXPECT_EQ(retries[0].first, 1U);
  EXPECT_EQ(retries[1].first, 2U);
}

TEST_F(ArpTest, AnAliveEntryExpiresAfterItsTimeout) {
  at(0.0, [this] { arp_.send(data(100), kNeighbor); });
  at(0.1, [this] { arp_.receive(reply_from(kNeighbor)); });
  at(120.0, [this] { arp_.send(data(101), kNeighbor); });  // 119.9 s after the reply: alive
  at(120.2, [this] { arp_.send(data(102), kNeighbor); });  // 120.1 s: expired, asks again
  scheduler_.run_until(from_seconds(120.5));
  EXPECT_EQ(link_.requests(), 2U);
  EXPECT_EQ(link_.sent[2].packet.uid, 101U);
  EXPECT_FALSE(arp_.resolved(kNeighbor));
}

TEST_F(ArpTest, ARequestIsAnsweredOnlyForOwnAddressAndTeachesNothing) {
  Packet request;
  request.source = 4;
  request.protocol = LinkProtocol::arp_request;
  request.destination = 9;  // somebody else's address
  at(0.0, [this, request] { arp_.receive(request); });
  request.destination = kSelf;
  at(0.1, [this, request] { arp_.receive(request); });
  scheduler_.run_until(from_seconds(1.0));
  ASSERT_EQ(link_.sent.size(), 1U);
  EXPECT_EQ(link_.sent[0].packet.protocol, LinkProtocol::arp_reply);
  EXPECT_EQ(link_.sent[0].next_hop, 4U);  // unicast, straight from the request's sender address
  EXPECT_EQ(link_.sent[0].packet.destination, 4U);
  EXPECT_FALSE(arp_.resolved(4));  // ns-3 learns no address from a request (its bug 107)
  EXPECT_EQ(arp_counter("replies_sent"), 1U);
}

TEST_F(ArpTest, AReplyNobodyWaitedForIsIgnored) {
  at(0.0, [this] { arp_.receive(reply_from(3)); });
  scheduler_.run_until(from_seconds(1.0));
  EXPECT_FALSE(arp_.resolved(3));
  EXPECT_TRUE(link_.sent.empty());
  EXPECT_EQ(arp_counter("replies_ignored"), 1U);
}

}  // namespace
}  // namespace swarmnet
