// The dcf80211 plugin's units: 802.11a timing, backoff counting and freezing, the interface
// queue, frame formats.
#include <gtest/gtest.h>

#include "channel_access.hpp"
#include "contention_window.hpp"
#include "dcf_timing.hpp"
#include "frame_format.hpp"
#include "interface_queue.hpp"

namespace swarmnet::dcf80211 {
namespace {

constexpr SimTime us(std::int64_t n) { return SimTime{n * 1000}; }

DcfTiming timing_80211a() { return DcfTiming(us(9), us(16), 6e6, 6e6); }

TEST(DcfTiming, Matches80211aAt6Mbps) {
  const DcfTiming t = timing_80211a();
  EXPECT_EQ(t.difs, us(34));
  // ACK: 16 + 112 + 6 bits = 134 -> 6 symbols of 24 bits: 20 + 24 us.
  EXPECT_EQ(t.ack_duration(), us(44));
  EXPECT_EQ(t.eifs, us(16 + 44 + 34));
  EXPECT_EQ(t.rts_duration(), us(52));  // 16 + 160 + 6 = 182 bits -> 8 symbols
  EXPECT_EQ(t.ack_timeout, us(16 + 9 + 20));
  // 1064-byte MPDU: 8534 bits -> 356 symbols.
  EXPECT_EQ(t.data_duration(1064), us(20 + 4 * 356));
  EXPECT_EQ(t.data_nav(true), us(16 + 44));
  EXPECT_EQ(t.data_nav(false), kTimeZero);
  EXPECT_EQ(t.rts_nav(1064), 3 * us(16) + us(44) + t.data_duration(1064) + us(44));
  EXPECT_EQ(t.cts_nav(t.rts_nav(1064)), 2 * us(16) + t.data_duration(1064) + us(44));
  EXPECT_THROW(DcfTiming(us(9), us(16), 7e6, 6e6), std::invalid_argument);
  const DcfTiming fast(us(9), us(16), 54e6, 24e6);
  EXPECT_EQ(fast.data_duration(1064), us(20 + 4 * 40));  // 8534 / 216 -> 40 symbols
}

TEST(DcfFrames, SizesAndDurationFields) {
  const DcfTiming t = timing_80211a();
  Packet packet;
  packet.header.resize(9);
  const Frame data = make_data(packet, 3, 36, 7, true, t);
  EXPECT_EQ(data.size_bytes(), 36U + kNetworkHeaderBytes + 9U);
  EXPECT_EQ(data.nav, t.data_nav(true));
  EXPECT_TRUE(data.retry);
  EXPECT_EQ(make_data(packet, kBroadcast, 36, 7, false, t).nav, kTimeZero);
  Frame rts = make_rts(3, 1000, t);
  rts.transmitter = 5;
  const Frame cts = make_cts(rts, t);
  EXPECT_EQ(cts.receiver, 5U);
  EXPECT_EQ(cts.type, FrameType::cts);
  EXPECT_EQ(airtime(rts, t), t.rts_duration());
  EXPECT_EQ(airtime(make_ack(1, t), t), t.ack_duration());
}

TEST(DcfContentionWindow, DoublesUpToTheMaximumAndResets) {
  ContentionWindow cw(15, 1023);
  const std::uint32_t expected[] = {31, 63, 127, 255, 511, 1023, 1023};
  for (const std::uint32_t value : expected) {
    cw.failed();
    EXPECT_EQ(cw.value(), value);
  }
  cw.reset();
  EXPECT_EQ(cw.value(), 15U);
  RandomStream random(3);
  std::uint32_t max_seen = 0;
  for (int i = 0; i < 2000; ++i) max_seen = std::max(max_seen, cw.draw(random));
  EXPECT_EQ(max_seen, 15U);  // uniform in [0, 15]
}

TEST(DcfChannelAccess, BackoffCountsIdleSlotsAfterDifs) {
  ChannelAccess access(timing_80211a());
  access.set_backoff(kTimeZero, 5);
  // Idle since 0: DIFS, then 5 slots.
  EXPECT_EQ(access.grant_time(kTimeZero), us(34 + 5 * 9));
  EXPECT_EQ(access.backoff_slots(us(34 + 2 * 9 + 3)), 3U);
}

TEST(DcfChannelAccess, BackoffFreezesWhileTheMediumIsBusy) {
  ChannelAccess access(timing_80211a());
  access.set_backoff(kTimeZero, 10);
  // Busy after DIFS + 3.5 slots: 3 whole slots counted, the interrupted one is not.
  const SimTime busy_at = us(34) + us(9) * 3 + us(4);
  access.medium_busy(busy_at);
  EXPECT_EQ(access.backoff_slots(busy_at), 7U);
  EXPECT_EQ(access.grant_time(busy_at), kTimeNever);
  // Frozen: a long busy period does not consume slots.
  EXPECT_EQ(access.backoff_slots(busy_at + us(5000)), 7U);
  const SimTime idle_at = busy_at + us(1000);
  access.medium_idle(idle_at);
  EXPECT_EQ(access.backoff_slots(idle_at + us(33)), 7U);  // DIFS not yet over
  EXPECT_EQ(access.grant_time(idle_at), idle_at + us(34) + us(9) * 7);
  // Busy again after 2 more slots; then idle after a failed reception: EIFS applies.
  access.medium_busy(idle_at + us(34 + 18));
  EXPECT_EQ(access.backoff_slots(idle_at + us(34 + 18)), 5U);
  const SimTime end = idle_at + us(2000);
  access.medium_idle(end);
  access.reception_ended(end, false);
  EXPECT_FALSE(access.idle_for_ifs(end + us(93)));
  EXPECT_TRUE(access.idle_for_ifs(end + us(94)));
  EXPECT_EQ(access.grant_time(end), end + us(94) + us(9) * 5);
}

TEST(DcfChannelAccess, NavDefersAndFreezes) {
  ChannelAccess access(timing_80211a());
  access.set_backoff(kTimeZero, 4);
  access.set_nav(us(34 + 9), us(500));  // one slot counted, then the NAV
  EXPECT_EQ(access.backoff_slots(us(400)), 3U);
  EXPECT_EQ(access.grant_time(us(400)), us(500 + 34 + 27));
  access.set_nav(us(410), us(450));  // never shortened
  EXPECT_EQ(access.nav_end(), us(500));
}

TEST(DcfChannelAccess, ZeroBackoffAfterDifsGrantsAtOnce) {
  ChannelAccess access(timing_80211a());
  access.set_backoff(kTimeZero, 0);
  EXPECT_EQ(access.grant_time(us(10)), us(34));
  EXPECT_EQ(access.grant_time(us(100)), us(100));
  EXPECT_TRUE(access.idle_for_ifs(us(100)));
}

TEST(DcfChannelAccess, DeferUntilHoldsAccessWithoutBackoff) {
  ChannelAccess access(timing_80211a());
  access.set_backoff(kTimeZero, 0);
  // Idle for long: a packet arriving at 500 us goes at 534 us (ns-3's backoff start now + DIFS).
  access.defer_until(us(500 + 34));
  EXPECT_EQ(access.backoff_slots(us(500)), 0U);
  EXPECT_EQ(access.grant_time(us(500)), us(534));
  // A busy period in between pushes it to DIFS after the busy period.
  access.medium_busy(us(510));
  EXPECT_EQ(access.grant_time(us(510)), kTimeNever);
  access.medium_idle(us(600));
  EXPECT_EQ(access.grant_time(us(600)), us(634));
}

TEST(DcfInterfaceQueue, BoundedFifoWithExpiry) {
  InterfaceQueue queue(2, us(1000));
  Packet a;
  a.uid = 1;
  Packet b;
  b.uid = 2;
  Packet c;
  c.uid = 3;
  EXPECT_TRUE(queue.push(a, 1, kTimeZero));
  EXPECT_TRUE(queue.push(b, 1, us(600)));
  EXPECT_TRUE(queue.full());
  EXPECT_FALSE(queue.push(c, 1, us(600)));
  std::vector<std::uint64_t> expired;
  const auto item =
      queue.pop(us(1500), [&](const InterfaceQueue::Item& i) { expired.push_back(i.packet.uid); });
  ASSERT_TRUE(item.has_value());
  EXPECT_EQ(item->packet.uid, 2U);
  EXPECT_EQ(expired, std::vector<std::uint64_t>{1});
  EXPECT_TRUE(queue.empty());
}

// As ns-3's WifiMacQueue keeps an MPDU until its exchange ends, the packet popped for an exchange
// keeps its place until released.
TEST(DcfInterfaceQueue, APoppedPacketKeepsItsPlaceUntilReleased) {
  InterfaceQueue queue(2, us(1000));
  Packet a;
  a.uid = 1;
  EXPECT_TRUE(queue.push(a, 1, kTimeZero));
  const auto item = queue.pop(us(10), [](const InterfaceQueue::Item&) {});
  ASSERT_TRUE(item.has_value());
  EXPECT_TRUE(queue.empty());
  EXPECT_TRUE(queue.push(a, 1, us(10)));
  EXPECT_TRUE(queue.full());  // one waiting, one held
  EXPECT_FALSE(queue.push(a, 1, us(10)));
  queue.release();
  EXPECT_FALSE(queue.full());
  EXPECT_TRUE(queue.push(a, 1, us(10)));
  EXPECT_TRUE(queue.full());
}

// ns-3's WifiMacQueue::Insert on a full queue removes the expired packets first.
TEST(DcfInterfaceQueue, TakesTheExpiredPacketsFromItsHead) {
  InterfaceQueue queue(3, us(1000));
  for (std::uint64_t uid = 1; uid <= 3; ++uid) {
    Packet p;
    p.uid = uid;
    EXPECT_TRUE(queue.push(p, static_cast<NodeId>(uid), us(400 * static_cast<int>(uid - 1))));
  }
  EXPECT_TRUE(queue.take_expired(us(1000)).empty());  // waited exactly the maximum: not expired
  const auto expired = queue.take_expired(us(1500));  // packets 1 and 2 waited 1.5 and 1.1 ms
  ASSERT_EQ(expired.size(), 2U);
  EXPECT_EQ(expired[0].packet.uid, 1U);
  EXPECT_EQ(expired[1].packet.uid, 2U);
  EXPECT_EQ(expired[1].next_hop, 2U);
  EXPECT_EQ(queue.size(), 1U);
}

}  // namespace
}  // namespace swarmnet::dcf80211
