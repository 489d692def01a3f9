// dcf80211's two ns-3.37 rules for a packet whose exchange does not end at once, each against the
// rule SwarmNet had before:
// - mpdu_lifetime: ns3 — ns-3's WifiMacQueue wipes expired MPDUs at every arrival, channel access
//   and release, the one under retransmission included (at_head: only as a packet reaches the
//   head; the packet being sent never expires);
// - retry_counters: station — the retry limits count WifiRemoteStationManager's SSRC/SLRC, one
//   per station, which an expiry does not reset (per_packet: each packet starts from zero).
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <string>

#include "dcf80211.hpp"
#include "frame_format.hpp"
#include "swarmnet/testing.hpp"

namespace swarmnet::dcf80211 {
namespace {

using testing::FakeMacContext;
using testing::PacketBuilder;
using testing::plugin_args;
using testing::TestScheduler;

constexpr NodeId kSelf = 0;

// One dcf80211 on a fake node, with the steps the tests take; a test may hold two.
class LifetimeBench {
 public:
  void make(const std::string& lifetime, const std::string& counters, double max_delay_s,
            std::int64_t short_retry_limit) {
    mac_ =
        std::make_unique<Dcf80211>(plugin_args<Dcf80211>({{"queue_max_delay_s", max_delay_s},
                                                          {"short_retry_limit", short_retry_limit},
                                                          {"mpdu_lifetime", lifetime},
                                                          {"retry_counters", counters}},
                                                         3, kSelf, 4));
    mac_->attach(node_);
  }
  void enqueue(std::uint64_t uid, NodeId next_hop) {
    mac_->enqueue(
        PacketBuilder().uid(uid).from(kSelf).to(next_hop).message(uid).payload_bytes(100).build(),
        next_hop);
  }
  void medium(bool busy) {
    node_.busy = busy;
    if (busy) {
      mac_->on_medium_busy();
    } else {
      mac_->on_medium_idle();
    }
  }
  // Runs until the MAC puts its next frame on the air (a backoff of 1023 slots is under 10 ms).
  const FakeMacContext::Transmission& next_frame() {
    const std::size_t sent = node_.transmitted.size();
    for (int us = 0; us < 10000 && node_.transmitted.size() == sent; ++us) {
      scheduler_.run_for(from_seconds(1e-6));
    }
    EXPECT_EQ(node_.transmitted.size(), sent + 1);
    return node_.transmitted.back();
  }
  // Ends the frame on the air and lets its ACK timeout pass.
  void end_without_ack() {
    mac_->on_transmit_end();
    scheduler_.run_for(mac_->timing().ack_timeout + from_seconds(1e-6));
  }
  void end_with_ack() {
    mac_->on_transmit_end();
    scheduler_.run_for(mac_->timing().sifs);
    mac_->on_receive(make_ack(kSelf, mac_->timing()), RxInfo{});
  }
  [[nodiscard]] std::size_t drops(DropReason reason, std::uint64_t uid = 0) const {
    std::size_t n = 0;
    for (const auto& d : node_.dropped) {
      n += d.reason == reason && (uid == 0 || d.packet.uid == uid) ? 1 : 0;
    }
    return n;
  }
  [[nodiscard]] std::size_t attempts_of(std::uint64_t uid) const {
    std::size_t n = 0;
    for (const auto& t : node_.transmitted) n += t.frame.packet && t.frame.packet->uid == uid;
    return n;
  }

  // Packet 1 waits for a busy medium past its lifetime; packet 2 came later and has not expired.
  const FakeMacContext::Transmission& expire_while_waiting() {
    medium(true);
    enqueue(1, 1);
    scheduler_.run_for(from_seconds(0.0008));
    enqueue(2, 2);
    scheduler_.run_for(from_seconds(0.0004));  // 1.2 ms: packet 1 outlived its 1 ms
    medium(false);
    return next_frame();
  }

 protected:
  TestScheduler scheduler_;
  FakeMacContext node_{scheduler_, kSelf, 4};
  std::unique_ptr<Dcf80211> mac_;
};

class Dcf80211Lifetime : public ::testing::Test, public LifetimeBench {};

class ExpiryWhileWaiting : public Dcf80211Lifetime {
 protected:
  const FakeMacContext::Transmission& run() { return expire_while_waiting(); }
};

TEST_F(ExpiryWhileWaiting, Ns3GivesTheAccessToTheNextPacket) {
  make("ns3", "station", 0.001, 7);
  const auto& frame = run();
  ASSERT_TRUE(frame.frame.packet);
  EXPECT_EQ(frame.frame.packet->uid, 2U);
  EXPECT_FALSE(frame.frame.retry);
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped[0].packet.uid, 1U);
  EXPECT_EQ(node_.dropped[0].reason, DropReason::buffer_timeout);
  ASSERT_EQ(node_.link_failures.size(), 1U);
  EXPECT_EQ(node_.link_failures[0].next_hop, 1U);
}

TEST_F(ExpiryWhileWaiting, AtHeadSendsThePacketItHasTaken) {
  make("at_head", "station", 0.001, 7);
  const auto& frame = run();
  ASSERT_TRUE(frame.frame.packet);
  EXPECT_EQ(frame.frame.packet->uid, 1U);
  EXPECT_TRUE(node_.dropped.empty());
}

// The access is the one packet 1 was granted: the same backoff, so the frame goes on the air at
// the same time under both rules (same seed), only another packet.
TEST(Dcf80211LifetimeAccess, TheNextPacketUsesTheSameAccess) {
  LifetimeBench ns3;
  LifetimeBench at_head;
  ns3.make("ns3", "station", 0.001, 7);
  at_head.make("at_head", "station", 0.001, 7);
  EXPECT_EQ(ns3.expire_while_waiting().at, at_head.expire_while_waiting().at);
}

// Packet 1 goes on the air and its lifetime ends before its ACK timeout; packet 2 arrives then.
class ExpiryDuringAnAttempt : public Dcf80211Lifetime {
 protected:
  void run_to_expiry() {
    enqueue(1, 1);
    next_frame();
    scheduler_.run_until(from_seconds(0.0011));  // still on the air, by the test's choice
    enqueue(2, 2);
  }
};

TEST_F(ExpiryDuringAnAttempt, Ns3ReportsItAtOnceAndDoesNotSendItAgain) {
  make("ns3", "station", 0.001, 7);
  run_to_expiry();
  ASSERT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.dropped[0].packet.uid, 1U);
  EXPECT_EQ(node_.dropped[0].reason, DropReason::buffer_timeout);
  ASSERT_EQ(node_.link_failures.size(), 1U);
  end_without_ack();
  const auto& frame = next_frame();
  EXPECT_EQ(frame.frame.packet->uid, 2U);
  EXPECT_FALSE(frame.frame.retry);
  EXPECT_EQ(attempts_of(1), 1U);
  EXPECT_EQ(node_.dropped.size(), 1U);  // counted once
}

TEST_F(ExpiryDuringAnAttempt, Ns3ReportsTheRetryLimitAgainWhenTheAttemptWasTheLast) {
  make("ns3", "station", 0.001, 1);
  run_to_expiry();
  end_without_ack();
  // ns-3's DroppedMpdu fires at the expiry and again at the retry limit; the drop counts once.
  EXPECT_EQ(node_.dropped.size(), 1U);
  ASSERT_EQ(node_.link_failures.size(), 2U);
  EXPECT_EQ(node_.link_failures[1].packet.uid, 1U);
  EXPECT_EQ(next_frame().frame.packet->uid, 2U);
}

TEST_F(ExpiryDuringAnAttempt, Ns3EndsTheExchangeNormallyIfTheAckComes) {
  make("ns3", "station", 0.001, 7);
  run_to_expiry();
  end_with_ack();
  EXPECT_EQ(next_frame().frame.packet->uid, 2U);
  EXPECT_EQ(node_.dropped.size(), 1U);
  EXPECT_EQ(node_.link_failures.size(), 1U);
}

TEST_F(ExpiryDuringAnAttempt, AtHeadRetransmitsIt) {
  make("at_head", "station", 0.001, 7);
  run_to_expiry();
  EXPECT_TRUE(node_.dropped.empty());
  end_without_ack();
  const auto& frame = next_frame();
  EXPECT_EQ(frame.frame.packet->uid, 1U);
  EXPECT_TRUE(frame.frame.retry);
}

// Packet 1 fails twice, then outlives its 10 ms while the medium is busy; packet 2 arrives after
// it, with time for all its attempts (the contention window stays as packet 1 left it).
class RetryCounts : public Dcf80211Lifetime {
 protected:
  void fail_twice_then_expire() {
    enqueue(1, 1);
    next_frame();
    end_without_ack();
    next_frame();
    end_without_ack();
    medium(true);
    scheduler_.run_until(from_seconds(0.012));
    enqueue(2, 2);  // wipes packet 1
    medium(false);
  }
  // Fails every attempt of packet 2 until the MAC gives it up.
  void fail_packet_2() {
    while (drops(DropReason::retry_limit, 2) == 0 && attempts_of(2) < 10) {
      next_frame();
      end_without_ack();
    }
  }
};

TEST_F(RetryCounts, TheStationsCountOutlivesAnExpiredPacket) {
  make("ns3", "station", 0.01, 3);
  fail_twice_then_expire();
  fail_packet_2();
  EXPECT_EQ(attempts_of(2), 1U);  // 3 - 2 attempts were left
  EXPECT_EQ(drops(DropReason::buffer_timeout, 1), 1U);
  EXPECT_EQ(drops(DropReason::retry_limit, 2), 1U);
}

TEST_F(RetryCounts, PerPacketCountsStartEachPacketFromZero) {
  make("ns3", "per_packet", 0.01, 3);
  fail_twice_then_expire();
  fail_packet_2();
  EXPECT_EQ(attempts_of(2), 3U);
  EXPECT_EQ(drops(DropReason::retry_limit, 2), 1U);
}

TEST_F(RetryCounts, AnAckResetsTheStationsCount) {
  make("ns3", "station", 0.5, 3);
  enqueue(1, 1);
  next_frame();
  end_without_ack();
  next_frame();
  end_with_ack();
  enqueue(2, 2);
  fail_packet_2();
  EXPECT_EQ(attempts_of(2), 3U);
}

TEST_F(RetryCounts, ADropAtTheLimitResetsTheStationsCount) {
  make("ns3", "station", 0.5, 2);
  enqueue(1, 1);
  enqueue(2, 2);
  for (int i = 0; i < 2; ++i) {
    next_frame();
    end_without_ack();
  }
  ASSERT_EQ(drops(DropReason::retry_limit), 1U);
  fail_packet_2();
  EXPECT_EQ(attempts_of(2), 2U);
}

}  // namespace
}  // namespace swarmnet::dcf80211
