// cbr: who sends, how often, what, to whom; and what receivers record.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <vector>

#include "plugins/controllers/cbr/sender_selection.hpp"
#include "robot/robot_world.hpp"
#include "robot_test_support.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet {
namespace {

using test::make_choice;
using test::make_settings;
using test::Overrides;

class CbrTest : public ::testing::Test {
 protected:
  // `count` robots standing still (no motion controller), cbr as controller entry 0.
  RobotSettings settings_for(std::uint32_t count, const Overrides& overrides,
                             std::uint64_t seed = 1) {
    RobotSettings s = make_settings(loader_, count, 30.0, 30.0, seed);
    s.robots.controllers.push_back(make_choice(loader_, "cbr", PluginKind::controller, overrides));
    return s;
  }

  // Runs `steps` steps and returns every message sent.
  static std::vector<AppMessage> run(RobotWorld& world, int steps) {
    std::vector<AppMessage> sent;
    for (int i = 0; i < steps; ++i) world.step({}, sent);
    return sent;
  }

  PluginLoader loader_;
};

std::set<RobotId> sources(const std::vector<AppMessage>& messages) {
  std::set<RobotId> result;
  for (const auto& message : messages) result.insert(message.source);
  return result;
}

TEST_F(CbrTest, ExactlyRoundedFractionOfRobotsSend) {
  for (const auto& [count, fraction, expected] :
       std::vector<std::tuple<std::uint32_t, double, std::size_t>>{
           {50, 0.2, 10}, {37, 0.3, 11}, {10, 0.25, 3}, {20, 1.0, 20}, {20, 0.0, 0}}) {
    RobotWorld world(settings_for(count, {{"fraction", fraction}, {"start_s", 0.0}}), loader_);
    EXPECT_EQ(sources(run(world, 20)).size(), expected) << count << " robots, " << fraction;
  }
}

// Every instance computes the same permutation from the shared seed: the robots that actually
// send are exactly the first round(fraction * N) of the shuffle of controller entry 0's shared
// stream. If instances disagreed, a different set (and usually count) would send.
TEST_F(CbrTest, SameSenderSetInEveryInstanceAndSeedDependent) {
  const std::uint32_t n = 60;
  std::set<std::set<RobotId>> sets;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    RobotWorld world(settings_for(n, {{"fraction", 0.25}, {"start_s", 0.0}}, seed), loader_);
    const auto actual = sources(run(world, 10));
    const std::uint64_t shared = derive_seed(seed, {hash_name("controller"), 0});
    const auto chosen = cbr::choose_senders(shared, n, 15, std::nullopt);
    EXPECT_EQ(actual, std::set<RobotId>(chosen.begin(), chosen.end())) << "seed " << seed;
    sets.insert(actual);
  }
  EXPECT_EQ(sets.size(), 4U);
}

TEST_F(CbrTest, EachSenderSendsAtTheConfiguredRateToOneOtherRobot) {
  const double rate = 7.0;  // not a multiple of 1 / step_s
  RobotWorld world(settings_for(40, {{"fraction", 0.5},
                                     {"rate_hz", rate},
                                     {"start_s", 2.0},
                                     {"payload_bytes", std::int64_t{100}}}),
                   loader_);
  std::map<RobotId, std::vector<std::uint64_t>> steps_of;  // step index of each send
  std::map<RobotId, std::set<RobotId>> destinations;
  std::vector<AppMessage> sent;
  for (std::uint64_t step = 0; step < 400; ++step) {  // 40 s
    sent.clear();
    world.step({}, sent);
    for (const auto& message : sent) {
      steps_of[message.source].push_back(step);
      destinations[message.source].insert(message.destination);
      ASSERT_EQ(message.payload.size(), 100U);
    }
  }
  ASSERT_EQ(steps_of.size(), 20U);
  for (const auto& [source, steps] : steps_of) {
    // First send at start_s + phase, phase in [0, 1 / rate): step 20, 21 or 22.
    EXPECT_GE(steps.front(), 20U);
    EXPECT_LE(steps.front(), 22U);
    // Over the 38-odd seconds after the start: rate * elapsed, within one message.
    const double elapsed_s = 39.9 - 2.0;
    EXPECT_NEAR(static_cast<double>(steps.size()), rate * elapsed_s, 1.5) << "robot " << source;
    // Any 10 s window holds 70 messages, within one.
    const auto in_window = std::count_if(steps.begin(), steps.end(),
                                         [](std::uint64_t s) { return s >= 200 && s < 300; });
    EXPECT_NEAR(static_cast<double>(in_window), 70.0, 1.0);
    ASSERT_EQ(destinations[source].size(), 1U);
    EXPECT_NE(*destinations[source].begin(), source);
    EXPECT_LT(*destinations[source].begin(), 40U);
  }
}

TEST_F(CbrTest, RatesAboveTheStepRateSendSeveralPerStep) {
  RobotWorld world(settings_for(10, {{"fraction", 0.1}, {"rate_hz", 25.0}, {"start_s", 0.0}}),
                   loader_);
  std::vector<AppMessage> sent;
  std::size_t total = 0;
  for (int step = 0; step < 100; ++step) {
    sent.clear();
    world.step({}, sent);
    if (step > 0) {
      EXPECT_GE(sent.size(), 2U);
      EXPECT_LE(sent.size(), 3U);
    }
    total += sent.size();
  }
  // Sends due at or before 9.9 s: 25 * 9.9 + 1, minus the phase, within one.
  EXPECT_NEAR(static_cast<double>(total), 25.0 * 9.9, 1.5);
}

TEST_F(CbrTest, PayloadCarriesTheSequenceNumberLittleEndian) {
  RobotWorld world(settings_for(5, {{"fraction", 0.2},
                                    {"rate_hz", 10.0},
                                    {"start_s", 0.0},
                                    {"payload_bytes", std::int64_t{32}}}),
                   loader_);
  const auto sent = run(world, 300);
  ASSERT_GE(sent.size(), 290U);
  for (std::size_t k = 0; k < sent.size(); ++k) {
    std::uint64_t sequence = 0;
    for (std::size_t b = 0; b < 8; ++b) {
      sequence |= static_cast<std::uint64_t>(sent[k].payload[b]) << (8 * b);
    }
    EXPECT_EQ(sequence, k);
    for (std::size_t b = 8; b < 32; ++b) ASSERT_EQ(sent[k].payload[b], std::byte{0});
  }
  EXPECT_GT(sent.back().payload[1], std::byte{0});  // sequence numbers above 255 use byte 1
}

TEST_F(CbrTest, NothingIsSentBeforeStart) {
  RobotWorld world(settings_for(20, {{"fraction", 1.0}, {"start_s", 3.0}}), loader_);
  EXPECT_TRUE(run(world, 30).empty());  // steps at 0.0 .. 2.9 s
  EXPECT_FALSE(run(world, 5).empty());
}

TEST_F(CbrTest, FixedDestinationReceivesFromEverySenderAndDoesNotSend) {
  RobotWorld world(
      settings_for(10, {{"fraction", 1.0}, {"destination", std::int64_t{4}}, {"start_s", 0.0}}),
      loader_);
  const auto sent = run(world, 10);
  const auto senders = sources(sent);
  EXPECT_EQ(senders.size(), 9U);
  EXPECT_FALSE(senders.contains(4));
  for (const auto& message : sent) EXPECT_EQ(message.destination, 4U);
}

TEST_F(CbrTest, DestinationThatIsNoRobotIsRefused) {
  EXPECT_THROW(RobotWorld(settings_for(10, {{"destination", std::int64_t{10}}}), loader_),
               std::invalid_argument);
}

// Receivers record the delay and hop count of messages from CBR senders addressed to them.
TEST_F(CbrTest, ReceiversRecordDelayOfTheirMessages) {
  RobotWorld world(settings_for(10, {{"fraction", 0.3},
                                     {"start_s", 0.0},
                                     {"rate_hz", 10.0},
                                     {"payload_bytes", std::int64_t{64}}}),
                   loader_);
  std::vector<AppMessage> sent;
  world.step({}, sent);  // t = 0: the first sends are due within [0, 0.1) s
  world.step({}, sent);
  ASSERT_FALSE(sent.empty());
  std::vector<Delivery> deliveries;
  double delay_sum = 0.0;
  for (const auto& message : sent) {
    Delivery delivery;
    delivery.message_id = message.message_id;
    delivery.source = message.source;
    delivery.destination = message.destination;
    delivery.receiver = message.destination;
    delivery.sent_at = from_seconds(0.0);
    delivery.delivered_at = from_seconds(0.01 * static_cast<double>(deliveries.size() + 1));
    delivery.hops = 2;
    delivery.payload = message.payload;
    delay_sum += to_seconds(delivery.delivered_at - delivery.sent_at);
    deliveries.push_back(delivery);
  }
  // Not counted: a broadcast copy, a message from a robot that is not a sender, a payload of
  // another size.
  Delivery broadcast = deliveries.front();
  broadcast.destination = kBroadcast;
  Delivery stranger = deliveries.front();
  stranger.source = stranger.destination == 0 ? 1 : 0;
  while (std::any_of(sent.begin(), sent.end(),
                     [&](const AppMessage& m) { return m.source == stranger.source; }) ||
         stranger.source == stranger.destination) {
    ++stranger.source;
  }
  Delivery other_size = deliveries.front();
  other_size.payload.resize(10);
  deliveries.push_back(broadcast);
  deliveries.push_back(stranger);
  deliveries.push_back(other_size);

  world.step(deliveries, sent);
  const auto& metrics = world.controller_metrics();
  ASSERT_TRUE(metrics.contains("cbr_received"));
  const MetricSummary& delay = metrics.find("cbr_received")->second;
  EXPECT_EQ(delay.count, deliveries.size() - 3);
  EXPECT_NEAR(delay.sum, delay_sum, 1e-12);
  EXPECT_NEAR(delay.min, 0.01, 1e-12);
  EXPECT_EQ(metrics.find("cbr_hops")->second.mean(), 2.0);

  // Inboxes last one step: nothing more is recorded on the next.
  world.step({}, sent);
  EXPECT_EQ(world.controller_metrics().find("cbr_received")->second.count, delay.count);
}

TEST(CbrSenderSelection, CountsAndExclusion) {
  EXPECT_EQ(cbr::sender_count(0.2, 50, false), 10U);
  EXPECT_EQ(cbr::sender_count(0.5, 5, false), 3U);  // 2.5 rounds up
  EXPECT_EQ(cbr::sender_count(1.0, 1, false), 0U);  // nobody to send to
  EXPECT_EQ(cbr::sender_count(1.0, 8, true), 7U);
  const auto chosen = cbr::choose_senders(99, 8, 7, RobotId{3});
  EXPECT_EQ(std::set<RobotId>(chosen.begin(), chosen.end()),
            (std::set<RobotId>{0, 1, 2, 4, 5, 6, 7}));
  EXPECT_EQ(cbr::choose_senders(5, 100, 20, std::nullopt),
            cbr::choose_senders(5, 100, 20, std::nullopt));
}

}  // namespace
}  // namespace swarmnet
