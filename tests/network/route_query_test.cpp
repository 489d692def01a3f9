// Route queries (RobotContext::route_to -> Routing::route_to): the network half answers each at
// its window's end from the routing plugin's state, and asking changes nothing it simulates.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "network/network_simulator.hpp"
#include "network/sensing_trace.hpp"
#include "network_test_support.hpp"

namespace swarmnet {
namespace {

// Runs `batches` step by step and returns each step's route answers.
std::vector<std::vector<RouteAnswer>> answers_per_step(const NetworkSettings& settings,
                                                       PluginLoader& loader,
                                                       const std::vector<StepBatch>& batches) {
  NetworkSimulator simulator(settings, loader, nullptr);
  std::vector<std::vector<RouteAnswer>> answers;
  StepResult result;
  for (const StepBatch& batch : batches) {
    simulator.run_step(batch, result);
    answers.push_back(result.routes);
  }
  return answers;
}

void ask_every_step(std::vector<StepBatch>& batches, const std::vector<RouteQuery>& queries) {
  for (StepBatch& batch : batches) batch.route_queries = queries;
}

// Three robots 100 m apart on a line (disk, 120 m): 0 reaches 2 through 1.
TEST(RouteQueries, AodvAnswersFromItsTableBeforeAndAfterTheRouteBreaks) {
  PluginLoader loader;
  const NetworkSettings settings = test::make_settings(loader, 3, "dcf80211", "aodv");
  std::vector<StepBatch> batches =
      test::fixed_batches(settings, test::line_positions(3, 100.0), 60, {});
  batches[5].messages.push_back(test::message(0, 0, 2));
  // Robot 2 leaves at 2 s; the next message finds the link gone (retry limit, then RERR).
  for (std::size_t step = 20; step < batches.size(); ++step)
    batches[step].positions[2] = {900, 900};
  batches[25].messages.push_back(test::message(1, 0, 2));
  ask_every_step(batches, {{0, 1}, {0, 2}});
  const auto answers = answers_per_step(settings, loader, batches);

  ASSERT_EQ(answers[0].size(), 2U);
  EXPECT_EQ(answers[0][0].query, (RouteQuery{0, 1}));
  EXPECT_EQ(answers[0][1].query, (RouteQuery{0, 2}));
  EXPECT_EQ(answers[0][1].route.status, RouteStatus::none);  // nothing sent yet
  EXPECT_EQ(answers[0][1].route.as_of, from_seconds(0.1));   // the window's end

  const Route found = answers[10][1].route;  // 0.5 s after the discovery
  ASSERT_EQ(found.status, RouteStatus::valid);
  EXPECT_EQ(found.next_hop, 1U);
  EXPECT_EQ(found.hops, 2U);
  const Route neighbour = answers[10][0].route;  // learnt from the RREP robot 1 relayed
  ASSERT_EQ(neighbour.status, RouteStatus::valid);
  EXPECT_EQ(neighbour.next_hop, 1U);
  EXPECT_EQ(neighbour.hops, 1U);

  // After the break: robot 1 gave up on 2 and told 0 (RERR), or 0's own route expired.
  EXPECT_EQ(answers[40][1].route.status, RouteStatus::none);
  EXPECT_EQ(answers[40][1].route.next_hop, kNoNode);
  EXPECT_EQ(answers[40][1].route.hops, 0U);
}

TEST(RouteQueries, AskingChangesNothingTheNetworkSimulates) {
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 12, "dcf80211", "aodv");
  settings.arena.width_m = 300.0;  // dense enough for multi-hop routes, sparse enough to break
  settings.arena.height_m = 300.0;
  std::vector<StepBatch> batches = test::random_batches(settings, 7, 80, 3, 0.2, 2.0);
  const test::RunOutput quiet = test::run(settings, loader, batches);
  std::vector<RouteQuery> everything;
  for (RobotId r = 0; r < 12; ++r) {
    for (RobotId d = 0; d < 12; ++d) {
      if (r != d) everything.push_back({r, d});
    }
  }
  ask_every_step(batches, everything);
  const test::RunOutput asked = test::run(settings, loader, batches);
  EXPECT_EQ(asked.trace, quiet.trace);
  EXPECT_EQ(asked.report.dump(), quiet.report.dump());
  EXPECT_EQ(asked.events_per_step, quiet.events_per_step);
  // The answers were about something: routes of several lengths, and destinations without one.
  std::set<std::uint32_t> lengths;
  std::size_t none = 0;
  for (const auto& step : answers_per_step(settings, loader, batches)) {
    for (const RouteAnswer& a : step) {
      if (a.route.status == RouteStatus::valid) lengths.insert(a.route.hops);
      if (a.route.status == RouteStatus::none) ++none;
    }
  }
  EXPECT_GE(lengths.size(), 2U);
  EXPECT_GT(none, 0U);
}

TEST(RouteQueries, FloodingTracksNoRoutesAndDirectAnswersItsOneHopRule) {
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 3, "ideal_mac", "flooding");
  std::vector<StepBatch> batches = test::fixed_batches(settings, test::line_positions(3, 100.0), 3,
                                                       {test::message(0, 0, kBroadcast)});
  ask_every_step(batches, {{0, 2}});
  auto answers = answers_per_step(settings, loader, batches);
  EXPECT_EQ(answers[2][0].route.status, RouteStatus::not_tracked);

  settings = test::make_settings(loader, 3, "ideal_mac", "direct");
  answers = answers_per_step(settings, loader, batches);
  const Route direct = answers[2][0].route;
  EXPECT_EQ(direct.status, RouteStatus::valid);  // its rule, not a measured link: 2 is far
  EXPECT_EQ(direct.next_hop, 2U);
  EXPECT_EQ(direct.hops, 1U);
}

TEST(RouteQueries, AQueryNamingNoOtherRobotIsRefusedBeforeTheWindow) {
  PluginLoader loader;
  const NetworkSettings settings = test::make_settings(loader, 3);
  std::vector<StepBatch> batches =
      test::fixed_batches(settings, test::line_positions(3, 100.0), 1, {});
  NetworkSimulator simulator(settings, loader, nullptr);
  StepResult result;
  for (const RouteQuery bad : {RouteQuery{1, 1}, RouteQuery{0, 3}, RouteQuery{5, 0}}) {
    batches[0].route_queries = {bad};
    EXPECT_THROW(simulator.run_step(batches[0], result), std::invalid_argument);
  }
  EXPECT_EQ(simulator.now(), kTimeZero);
}

// With a sensing trace (output.sensing_trace) the simulator writes, window by window, exactly
// the rows of what it returned (neighbour tables, send reports, route answers), and simulates
// the same: its packet trace is the one of a simulator without it.
TEST(RouteQueries, TheSensingTraceHoldsWhatEveryWindowReturnedAndChangesNothing) {
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 12, "dcf80211", "aodv");
  settings.arena.width_m = 300.0;
  settings.arena.height_m = 300.0;
  settings.network.neighbors.enabled = true;
  std::vector<StepBatch> batches = test::random_batches(settings, 7, 40, 3, 0.2, 2.0);
  for (StepBatch& batch : batches) {
    for (AppMessage& message : batch.messages) message.report = message.message_id % 2 == 0;
  }
  ask_every_step(batches, {{0, 5}, {3, 1}, {3, 7}});

  std::ostringstream sensing;
  std::ostringstream packets;
  std::ostringstream expected;
  SensingTraceWriter returned(&expected);
  {
    NetworkSimulator simulator(settings, loader, &packets, nullptr, &sensing);
    StepResult result;
    for (const StepBatch& batch : batches) {
      simulator.run_step(batch, result);
      returned.record(result, simulator.now());
    }
    simulator.finish();
  }
  returned.finish();
  const std::string text = sensing.str();
  EXPECT_EQ(text, expected.str());
  for (const char* record : {",neighbor,", ",report,", ",route,"}) {
    EXPECT_NE(text.find(record), std::string::npos) << record;
  }
  EXPECT_EQ(packets.str(), test::run(settings, loader, batches).trace);
}

}  // namespace
}  // namespace swarmnet
