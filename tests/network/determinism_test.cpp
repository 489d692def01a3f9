// A run is a pure function of its inputs: same settings and batches, same bytes out.
#include <gtest/gtest.h>

#include "network/network_simulator.hpp"
#include "network_test_support.hpp"
#include "outputs/run_summary.hpp"

namespace swarmnet {
namespace {

NetworkSettings random_settings(PluginLoader& loader) {
  NetworkSettings settings = test::make_settings(loader, 60);
  settings.arena.width_m = 500.0;
  settings.arena.height_m = 500.0;
  test::set_param(settings.network.propagation[0], "probability", 0.7);
  return settings;
}

TEST(NetworkDeterminism, SameInputsGiveIdenticalTraceAndReport) {
  PluginLoader loader;
  const NetworkSettings settings = random_settings(loader);
  const auto batches = test::random_batches(settings, 3, 25, 8, 0.3, 3.0);
  const auto first = test::run(settings, loader, batches);
  const auto second = test::run(settings, loader, batches);
  ASSERT_GT(first.deliveries.size(), 50U);
  EXPECT_TRUE(first.trace == second.trace) << "packet traces differ";
  EXPECT_EQ(first.report.dump(), second.report.dump());
  EXPECT_EQ(first.events_per_step, second.events_per_step);
}

TEST(NetworkDeterminism, TheSeedChangesTheRun) {
  PluginLoader loader;
  NetworkSettings settings = random_settings(loader);
  const auto batches = test::random_batches(settings, 3, 10, 8, 0.3, 3.0);
  const auto first = test::run(settings, loader, batches);
  settings.seed = 2;
  const auto second = test::run(settings, loader, batches);
  EXPECT_NE(first.trace, second.trace);
}

TEST(NetworkDeterminism, StepEventCountsAddUpToTheReport) {
  PluginLoader loader;
  const NetworkSettings settings = random_settings(loader);
  const auto out = test::run(settings, loader, test::random_batches(settings, 5, 10, 8, 0.3, 3.0));
  std::uint64_t total = 0;
  for (const std::uint64_t events : out.events_per_step) total += events;
  EXPECT_GT(total, 0U);
  EXPECT_EQ(out.report["events"].get<std::uint64_t>(), total);
}

TEST(NetworkSimulator, ReportHasEveryKeyWithZerosIncluded) {
  PluginLoader loader;
  const NetworkSettings settings = test::make_settings(loader, 2);
  const NetworkSimulator simulator(settings, loader, nullptr);
  const auto report = network_report_json(simulator.report());
  const char* keys[] = {"packets", "pdr",     "delay_s", "hops_mean",
                        "mac",     "routing", "arp",     "events"};
  std::size_t i = 0;
  for (const auto& [key, value] : report.items()) {
    ASSERT_LT(i, std::size(keys));
    EXPECT_EQ(key, keys[i++]);
  }
  EXPECT_EQ(i, std::size(keys));
  for (const char* reason : {"no_route", "queue_full", "ttl_expired", "retry_limit",
                             "buffer_timeout", "arp_queue_full", "arp_unresolved"}) {
    EXPECT_EQ(report["packets"]["dropped"][reason], 0) << reason;
  }
  for (const char* key :
       {"sent", "delivered", "broadcast_sent", "broadcast_deliveries", "undelivered"}) {
    EXPECT_EQ(report["packets"][key], 0) << key;
  }
  for (const char* key : {"tx_frames", "tx_bytes", "collisions", "retries"}) {
    EXPECT_EQ(report["mac"][key], 0) << key;
  }
  for (const char* key : {"control_packets", "control_bytes", "data_forwards"}) {
    EXPECT_EQ(report["routing"][key], 0) << key;
  }
  for (const char* key : {"requests_sent", "replies_sent", "resolved", "failed", "replies_ignored",
                          "frames_dropped"}) {
    EXPECT_EQ(report["arp"][key], 0) << key;
  }
  EXPECT_EQ(report["pdr"].get<double>(), 0.0);
  EXPECT_TRUE(report["delay_s"]["p95"].is_null());
}

TEST(NetworkSimulator, RefusesMalformedBatches) {
  PluginLoader loader;
  const NetworkSettings settings = test::make_settings(loader, 3);
  NetworkSimulator simulator(settings, loader, nullptr);
  StepResult result;
  auto batches = test::fixed_batches(settings, test::line_positions(3, 50.0), 2, {});
  StepBatch wrong_count = batches[0];
  wrong_count.positions.pop_back();
  EXPECT_THROW(simulator.run_step(wrong_count, result), std::invalid_argument);
  StepBatch unknown_robot = batches[0];
  unknown_robot.messages.push_back(test::message(0, 0, 7));
  EXPECT_THROW(simulator.run_step(unknown_robot, result), std::invalid_argument);
  simulator.run_step(batches[1], result);
  EXPECT_EQ(simulator.now(), SimTime{200'000'000});
  EXPECT_THROW(simulator.run_step(batches[0], result), std::invalid_argument);  // in the past
}

}  // namespace
}  // namespace swarmnet
