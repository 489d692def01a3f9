// Radio neighbour tables (network.neighbors): against hand-fed frames, then through the
// simulator on hand-built layouts, where they must list exactly the nodes whose frames the PHY
// decoded.
#include "network/neighbor_tables.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "network/network_simulator.hpp"
#include "network_test_support.hpp"

namespace swarmnet {
namespace {

SimTime ms(std::int64_t n) { return SimTime{n * 1'000'000}; }

Frame frame_from(NodeId transmitter, FrameType type = FrameType::data) {
  Frame f;
  f.type = type;
  f.transmitter = transmitter;
  return f;
}

struct Tables {
  std::vector<std::uint32_t> counts;
  std::vector<RadioNeighbor> entries;
};

Tables collect(NeighborTables& tables, SimTime now) {
  Tables t;
  tables.collect(now, t.counts, t.entries);
  return t;
}

TEST(NeighborTables, ListWhatEachNodeDecodedAscendingWithRssiSinrAndFrames) {
  NeighborSensing settings;
  settings.rssi_smoothing = 0.5;
  NeighborTables tables(3, settings);
  tables.heard(0, frame_from(2), RxInfo{-70.0, 20.0}, ms(10));
  tables.heard(0, frame_from(1), RxInfo{-60.0, 30.0}, ms(20));
  tables.heard(0, frame_from(2), RxInfo{-80.0, 10.0}, ms(30));
  tables.heard(0, frame_from(1, FrameType::ack), RxInfo{-50.0, 40.0}, ms(40));  // names no sender
  tables.heard(0, frame_from(2, FrameType::cts), RxInfo{-50.0, 40.0}, ms(40));
  tables.heard(0, frame_from(0), RxInfo{-10.0, 90.0}, ms(40));  // its own frame
  const Tables t = collect(tables, ms(100));
  ASSERT_EQ(t.counts, (std::vector<std::uint32_t>{2, 0, 0}));
  EXPECT_EQ(t.entries[0].id, 1U);
  EXPECT_EQ(t.entries[0].frames, 1U);
  EXPECT_EQ(t.entries[0].last_heard, ms(20));
  EXPECT_EQ(t.entries[1].id, 2U);
  EXPECT_EQ(t.entries[1].frames, 2U);
  EXPECT_EQ(t.entries[1].last_heard, ms(30));
  EXPECT_EQ(t.entries[1].rssi_dbm, -80.0);
  EXPECT_EQ(t.entries[1].rssi_smoothed_dbm, -75.0);  // -70 + 0.5 x (-80 - -70)
  EXPECT_EQ(t.entries[1].sinr_db, 10.0);
}

TEST(NeighborTables, ANodeSilentForTheWholeWindowAgesOutAndOldFramesStopCounting) {
  NeighborSensing settings;
  settings.window_s = 1.0;
  NeighborTables tables(2, settings);
  tables.heard(1, frame_from(0), RxInfo{-70.0, 20.0}, ms(100));
  tables.heard(1, frame_from(0), RxInfo{-70.0, 20.0}, ms(900));
  Tables t = collect(tables, ms(1000));
  ASSERT_EQ(t.counts[1], 1U);
  EXPECT_EQ(t.entries[0].frames, 2U);
  t = collect(tables, ms(1500));  // the frame at 0.1 s has left the window
  ASSERT_EQ(t.counts[1], 1U);
  EXPECT_EQ(t.entries[0].frames, 1U);
  t = collect(tables, ms(1900));  // heard last exactly a window ago: gone
  EXPECT_EQ(t.counts[1], 0U);
  EXPECT_TRUE(t.entries.empty());
}

TEST(NeighborTables, AFullTableKeepsTheMostRecentlyHeard) {
  NeighborSensing settings;
  settings.max_per_robot = 2;
  NeighborTables tables(5, settings);
  tables.heard(0, frame_from(4), RxInfo{-70.0, 20.0}, ms(10));
  tables.heard(0, frame_from(3), RxInfo{-70.0, 20.0}, ms(30));
  tables.heard(0, frame_from(1), RxInfo{-70.0, 20.0}, ms(20));
  tables.heard(0, frame_from(2), RxInfo{-70.0, 20.0}, ms(30));  // ties with 3: the lower id first
  const Tables t = collect(tables, ms(100));
  ASSERT_EQ(t.counts[0], 2U);
  EXPECT_EQ(t.entries[0].id, 2U);
  EXPECT_EQ(t.entries[1].id, 3U);
}

TEST(NeighborTables, UnicastExchangesCountIntoTheHeardNeighboursEntryAndAgeOut) {
  NeighborSensing settings;
  settings.window_s = 1.0;
  NeighborTables tables(3, settings);
  tables.heard(0, frame_from(1), RxInfo{-70.0, 20.0}, ms(100));
  tables.exchange_ended(0, 1, true, 1, ms(200));   // first attempt
  tables.exchange_ended(0, 1, true, 3, ms(300));   // third attempt
  tables.exchange_ended(0, 1, false, 7, ms(900));  // given up
  tables.exchange_ended(0, 2, true, 1, ms(400));   // 2 was never heard: no entry for it
  Tables t = collect(tables, ms(1000));
  ASSERT_EQ(t.counts[0], 1U);
  EXPECT_EQ(t.entries[0].id, 1U);
  EXPECT_EQ(t.entries[0].unicasts, 3U);
  EXPECT_EQ(t.entries[0].first_attempt_acks, 1U);
  ASSERT_TRUE(t.entries[0].first_attempt_ack_share().has_value());
  EXPECT_DOUBLE_EQ(*t.entries[0].first_attempt_ack_share(), 1.0 / 3.0);
  // Heard again at 1.05 s; by 1.25 s the exchanges at 0.2 s have left the window.
  tables.heard(0, frame_from(1), RxInfo{-70.0, 20.0}, ms(1050));
  t = collect(tables, ms(1250));
  ASSERT_EQ(t.counts[0], 1U);
  EXPECT_EQ(t.entries[0].unicasts, 2U);
  EXPECT_EQ(t.entries[0].first_attempt_acks, 0U);
  // Heard after its exchange with 0 left the window: an entry without any.
  tables.heard(0, frame_from(2), RxInfo{-70.0, 20.0}, ms(1500));
  t = collect(tables, ms(1950));
  ASSERT_EQ(t.counts[0], 2U);
  EXPECT_EQ(t.entries[0].unicasts, 0U);
  EXPECT_FALSE(t.entries[0].first_attempt_ack_share().has_value());
  EXPECT_EQ(t.entries[1].unicasts, 0U);
}

// Three robots on a line 100 m apart, 120 m disk: the ends hear only the middle one.
TEST(NetworkNeighborTables, TheSimulatorListsTheNodesWhoseFramesThePhyDecoded) {
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 3);
  settings.network.neighbors.enabled = true;
  NetworkSimulator simulator(settings, loader, nullptr);
  const std::vector<StepBatch> batches =
      test::fixed_batches(settings, test::line_positions(3, 100.0), 3,
                          {test::message(0, 0, kBroadcast), test::message(1, 1, kBroadcast),
                           test::message(2, 2, kBroadcast)});
  StepResult result;
  simulator.run_step(batches[0], result);
  ASSERT_EQ(result.neighbor_counts, (std::vector<std::uint32_t>{1, 2, 1}));
  EXPECT_EQ(result.neighbors[0].id, 1U);
  EXPECT_EQ(result.neighbors[1].id, 0U);
  EXPECT_EQ(result.neighbors[2].id, 2U);
  EXPECT_EQ(result.neighbors[3].id, 1U);
  for (const RadioNeighbor& n : result.neighbors) {
    EXPECT_GE(n.frames, 1U);
    EXPECT_TRUE(std::isfinite(n.rssi_dbm));
    EXPECT_GT(n.last_heard, kTimeZero);
    EXPECT_LE(n.last_heard, from_seconds(0.1));
  }
  // No more traffic: a second later every table has emptied.
  for (std::uint64_t step = 1; step < 12; ++step) {
    StepBatch quiet;
    quiet.step = step;
    quiet.start = from_seconds(0.1) * static_cast<std::int64_t>(step);
    quiet.positions = test::line_positions(3, 100.0);
    simulator.run_step(quiet, result);
  }
  EXPECT_EQ(result.neighbor_counts, (std::vector<std::uint32_t>{0, 0, 0}));
}

// Robot 1 in the middle broadcasts (so that the others hear it) and receives unicasts: from 0
// alone, or from 0 and 2, which cannot hear each other (a hidden terminal) and so collide at 1.
struct ExchangeCounts {
  std::uint32_t unicasts = 0;
  std::uint32_t first_attempt_acks = 0;
};

ExchangeCounts exchanges_with_the_middle(bool hidden_terminal) {
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 3, "dcf80211", "direct");
  settings.network.neighbors.enabled = true;
  settings.network.neighbors.window_s = 10.0;
  settings.network.arp.reset();  // static ARP: every exchange is a data frame and its ACK
  settings.network.phy.model = PhyModel::sinr;  // overlapping frames interfere
  std::vector<StepBatch> batches =
      test::fixed_batches(settings, test::line_positions(3, 100.0), 30, {});
  std::uint64_t id = 0;
  for (std::uint64_t step = 0; step < 20; ++step) {
    batches[step].messages.push_back(test::message(id++, 1, kBroadcast, 50));
    for (int k = 0; k < 8; ++k) {
      batches[step].messages.push_back(test::message(id++, 0, 1, 1000));
      if (hidden_terminal) batches[step].messages.push_back(test::message(id++, 2, 1, 1000));
    }
  }
  NetworkSimulator simulator(settings, loader, nullptr);
  StepResult result;
  for (const StepBatch& batch : batches) simulator.run_step(batch, result);
  ExchangeCounts counts;
  // Robot 0's table is the first; robot 2's the last: both list robot 1 alone.
  EXPECT_EQ(result.neighbor_counts[0], 1U);
  EXPECT_EQ(result.neighbor_counts[2], 1U);
  for (const RobotId table : {0U, 2U}) {
    const std::size_t at = table == 0 ? 0 : result.neighbors.size() - 1;
    const RadioNeighbor& middle = result.neighbors[at];
    EXPECT_EQ(middle.id, 1U);
    EXPECT_LE(middle.first_attempt_acks, middle.unicasts);
    counts.unicasts += middle.unicasts;
    counts.first_attempt_acks += middle.first_attempt_acks;
  }
  return counts;
}

TEST(NetworkNeighborTables, AHiddenTerminalsCollisionsShowInTheShareAcknowledgedAtFirstAttempt) {
  const ExchangeCounts alone = exchanges_with_the_middle(false);
  EXPECT_EQ(alone.unicasts, 160U);  // every exchange of robot 0 ended inside the 10 s window
  EXPECT_EQ(alone.first_attempt_acks, alone.unicasts);
  const ExchangeCounts hidden = exchanges_with_the_middle(true);
  EXPECT_EQ(hidden.unicasts, 320U);  // retried until acknowledged or given up: each ends once
  EXPECT_LT(hidden.first_attempt_acks, hidden.unicasts * 85 / 100);
}

TEST(NetworkNeighborTables, WithoutNetworkNeighborsNoTableIsKept) {
  PluginLoader loader;
  const NetworkSettings settings = test::make_settings(loader, 3);
  NetworkSimulator simulator(settings, loader, nullptr);
  StepResult result;
  simulator.run_step(test::fixed_batches(settings, test::line_positions(3, 100.0), 1,
                                         {test::message(0, 0, kBroadcast)})[0],
                     result);
  EXPECT_TRUE(result.neighbor_counts.empty());
  EXPECT_TRUE(result.neighbors.empty());
}

}  // namespace
}  // namespace swarmnet
