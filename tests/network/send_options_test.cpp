// Send options and send reports in the network half (swarmnet/send_report.hpp): a hop limit
// ends a message's travel under flooding and AODV, and a message that asks gets one report of
// its fate at its own node, for every outcome its stack can meet there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "network_test_support.hpp"

namespace swarmnet {
namespace {

std::set<RobotId> receivers(const test::RunOutput& out, std::uint64_t message_id) {
  std::set<RobotId> seen;
  for (const Delivery& d : out.deliveries) {
    if (d.message_id == message_id) seen.insert(d.receiver);
  }
  return seen;
}

AppMessage with_options(AppMessage message, std::uint8_t hop_limit, bool report) {
  message.hop_limit = hop_limit;
  message.report = report;
  return message;
}

// Four robots 100 m apart on a line: each hears only its neighbours (disk, 120 m).
class HopLimit : public ::testing::TestWithParam<const char*> {
 protected:
  HopLimit() : settings_(test::make_settings(loader_, 4, "ideal_mac", GetParam())) {}
  test::RunOutput run(std::vector<AppMessage> messages) {
    return test::run(
        settings_, loader_,
        test::fixed_batches(settings_, test::line_positions(4, 100.0), 20, std::move(messages)));
  }
  PluginLoader loader_;
  NetworkSettings settings_;
};

TEST_P(HopLimit, ABroadcastTravelsAsManyLinksAsItsLimitAndNoFurther) {
  const auto out = run({with_options(test::message(0, 0, kBroadcast), 1, false),
                        with_options(test::message(1, 0, kBroadcast), 2, false),
                        with_options(test::message(2, 0, kBroadcast), 0, false)});
  EXPECT_EQ(receivers(out, 0), (std::set<RobotId>{1}));
  EXPECT_EQ(receivers(out, 1), (std::set<RobotId>{1, 2}));
  EXPECT_EQ(receivers(out, 2), (std::set<RobotId>{1, 2, 3}));
  // A broadcast that reached its scope is not lost: no drop is counted for it.
  for (const auto& line : test::parse_trace(out.trace)) {
    EXPECT_NE(line.event, "drop") << line.message_id << " at " << line.node << ": " << line.detail;
  }
  // One transmission for the one-hop beacon: the neighbour does not relay it.
  const auto lines = test::parse_trace(out.trace);
  EXPECT_EQ(std::count_if(lines.begin(), lines.end(),
                          [](const test::TraceLine& l) {
                            return l.event == "forward" && l.message_id == "0";
                          }),
            0);
}

TEST_P(HopLimit, AUnicastBeyondItsLimitIsDroppedWhereTheLimitRunsOut) {
  // A message without a limit first (AODV finds the route with it), then one limited to one
  // link, 1 s later: the first relay drops it.
  auto batches =
      test::fixed_batches(settings_, test::line_positions(4, 100.0), 40, {test::message(0, 0, 3)});
  batches[10].messages.push_back(with_options(test::message(1, 0, 3), 1, false));
  const auto out = test::run(settings_, loader_, batches);
  EXPECT_EQ(receivers(out, 0), (std::set<RobotId>{3}));
  EXPECT_TRUE(receivers(out, 1).empty());
  const auto lines = test::parse_trace(out.trace);
  const auto drop = std::find_if(lines.begin(), lines.end(), [](const test::TraceLine& l) {
    return l.event == "drop" && l.message_id == "1";
  });
  ASSERT_NE(drop, lines.end());
  EXPECT_EQ(drop->node, 1);
  EXPECT_EQ(drop->detail, "ttl_expired");
}

INSTANTIATE_TEST_SUITE_P(Routing, HopLimit, ::testing::Values("flooding", "aodv"));

// Send reports: two robots in range, a third far out of it.
class SendReportsRun : public ::testing::Test {
 protected:
  void use(const std::string& mac, const std::string& routing) {
    settings_ = test::make_settings(loader_, 3, mac, routing);
  }
  std::vector<AddressedSendReport> run(std::vector<AppMessage> messages, std::uint64_t steps = 20) {
    const std::vector<Vec2> positions = {{10, 50}, {110, 50}, {900, 900}};
    reports_.clear();
    out_ =
        test::run(settings_, loader_,
                  test::fixed_batches(settings_, positions, steps, std::move(messages)), &reports_);
    return reports_;
  }
  static AppMessage reported(std::uint64_t id, RobotId source, RobotId destination,
                             std::size_t bytes = 100) {
    return with_options(test::message(id, source, destination, bytes), 0, true);
  }
  PluginLoader loader_;
  NetworkSettings settings_;
  test::RunOutput out_;
  std::vector<AddressedSendReport> reports_;
};

TEST_F(SendReportsRun, AnAcknowledgedUnicastNamesItsFirstHopAndItsAttempts) {
  use("dcf80211", "direct");
  AppMessage m = reported(4, 0, 1);
  m.port = 7;
  const auto reports = run({m});
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].source, 0U);
  EXPECT_EQ(reports[0].port, 7);
  EXPECT_EQ(reports[0].report.message_id, 4U);
  EXPECT_EQ(reports[0].report.outcome, SendOutcome::acknowledged);
  EXPECT_EQ(reports[0].report.next_hop, 1U);
  EXPECT_EQ(reports[0].report.attempts, 1U);
  ASSERT_EQ(out_.deliveries.size(), 1U);
  // The ACK comes after the data frame arrived.
  EXPECT_GT(reports[0].report.at, out_.deliveries[0].delivered_at);
}

TEST_F(SendReportsRun, ABroadcastIsSentAndAUnicastUnderAMacWithoutAcksToo) {
  use("dcf80211", "direct");
  auto reports = run({reported(0, 0, kBroadcast)});
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].report.outcome, SendOutcome::sent);
  EXPECT_EQ(reports[0].report.next_hop, kBroadcast);
  EXPECT_EQ(reports[0].report.attempts, 0U);

  use("ideal_mac", "direct");
  settings_.network.arp.reset();  // static ARP: the frame to robot 2 goes on the air too
  reports = run({reported(0, 0, 1), reported(1, 0, 2)});  // 2 is out of range: no MAC can tell
  ASSERT_EQ(reports.size(), 2U);
  for (const auto& r : reports) {
    EXPECT_EQ(r.report.outcome, SendOutcome::sent);
    EXPECT_EQ(r.report.next_hop, r.report.message_id == 0 ? 1U : 2U);  // in injection order
  }
}

TEST_F(SendReportsRun, OnlyTheMessagesThatAskAreReportedAndEachOnce) {
  use("dcf80211", "flooding");  // every robot relays: copies pass the source again
  const auto reports =
      run({test::message(0, 0, kBroadcast), reported(1, 0, kBroadcast), test::message(2, 1, 0)});
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].report.message_id, 1U);
  EXPECT_EQ(reports[0].report.outcome, SendOutcome::sent);
}

TEST_F(SendReportsRun, AMessageToItselfIsSentAtOnce) {
  use("ideal_mac", "direct");
  const auto reports = run({reported(0, 1, 1)});
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].report.outcome, SendOutcome::sent);
  EXPECT_EQ(reports[0].report.next_hop, 1U);
  ASSERT_EQ(out_.deliveries.size(), 1U);
  EXPECT_EQ(reports[0].report.at, out_.deliveries[0].sent_at);
}

// Every reason a source's own stack discards a message for, each forced. (ttl_expired is met
// only at relays: a source sends whatever its limit.)
TEST_F(SendReportsRun, TheMacsRetryLimitIsADropWithItsReason) {
  use("dcf80211", "direct");
  settings_.network.arp.reset();  // static ARP: the data frame itself goes unanswered
  const auto reports = run({reported(0, 0, 2)});
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].report.outcome, SendOutcome::dropped);
  EXPECT_EQ(reports[0].report.reason, DropReason::retry_limit);
  EXPECT_EQ(reports[0].report.next_hop, kNoNode);
}

TEST_F(SendReportsRun, ArpUnresolvedAndArpQueueFull) {
  use("ideal_mac", "direct");
  // ARP holds three packets per unresolved neighbour; the fourth and fifth are refused, and the
  // three it held die with the entry after its retries (about 4 s).
  std::vector<AppMessage> messages;
  for (std::uint64_t i = 0; i < 5; ++i) messages.push_back(reported(i, 0, 2));
  const auto reports = run(messages, 60);
  ASSERT_EQ(reports.size(), 5U);
  std::multiset<DropReason> reasons;
  for (const auto& r : reports) {
    EXPECT_EQ(r.report.outcome, SendOutcome::dropped);
    reasons.insert(r.report.reason);
  }
  EXPECT_EQ(reasons.count(DropReason::arp_queue_full), 2U);
  EXPECT_EQ(reasons.count(DropReason::arp_unresolved), 3U);
  // In the order they happened: refusals at once, the deaths seconds later.
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end(), [](const auto& a, const auto& b) {
    return a.report.at < b.report.at;
  }));
}

TEST_F(SendReportsRun, AFullInterfaceQueue) {
  use("ideal_mac", "direct");
  settings_.network.arp.reset();
  test::set_param(settings_.network.mac, "queue_limit", std::int64_t{1});
  test::set_param(settings_.network.mac, "bitrate_bps", 1000.0);  // a frame takes about a second
  std::vector<AppMessage> messages;
  for (std::uint64_t i = 0; i < 4; ++i) messages.push_back(reported(i, 0, 1));
  const auto reports = run(messages, 80);
  ASSERT_EQ(reports.size(), 4U);
  std::size_t full = 0;
  for (const auto& r : reports) {
    if (r.report.outcome == SendOutcome::dropped) {
      EXPECT_EQ(r.report.reason, DropReason::queue_full);
      ++full;
    }
  }
  EXPECT_EQ(full, 2U);  // one on the air, one queued, two refused
}

TEST_F(SendReportsRun, AodvsNoRouteAndBufferTimeout) {
  use("ideal_mac", "aodv");
  auto reports = run({reported(0, 0, 2)}, 200);  // 20 s: every RREQ retry goes unanswered
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].report.outcome, SendOutcome::dropped);
  EXPECT_EQ(reports[0].report.reason, DropReason::no_route);

  test::set_param(settings_.network.routing, "max_queue_time_s", 0.5);
  reports = run({reported(0, 0, 2)}, 200);
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].report.reason, DropReason::buffer_timeout);

  // Its route request queue full: max_queue_len 1 keeps the newest.
  test::set_param(settings_.network.routing, "max_queue_time_s", 30.0);
  test::set_param(settings_.network.routing, "max_queue_len", std::int64_t{1});
  reports = run({reported(0, 0, 2), reported(1, 0, 2)}, 200);
  ASSERT_EQ(reports.size(), 2U);
  EXPECT_EQ(reports[0].report.reason, DropReason::queue_full);
  EXPECT_EQ(reports[1].report.reason, DropReason::no_route);
}

}  // namespace
}  // namespace swarmnet
