// The step protocol's records: round trips, and clear errors for malformed or unexpected input.
#include "protocol/step_channel.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "inproc_channel.hpp"
#include "protocol/record_codec.hpp"

namespace swarmnet {
namespace {

// A record of `fields`, encoded by hand to feed the channel what a broken peer would send.
template <typename... Fields>
std::vector<std::byte> encode(const Fields&... fields) {
  std::vector<std::byte> record((encoded_bytes(fields) + ...));
  RecordWriter writer(record);
  (writer.put(fields), ...);
  return record;
}

StepBatch sample_batch(std::uint32_t robots, std::uint32_t messages) {
  StepBatch batch;
  batch.step = 0;  // a channel's first step, as the handshake's limits require
  batch.start = SimTime{0};
  for (std::uint32_t i = 0; i < robots; ++i) batch.positions.emplace_back(i * 1.5, 1000.0 - i);
  for (std::uint32_t i = 0; i < messages; ++i) {
    AppMessage m;
    m.message_id = 100 + i;
    m.source = i % robots;
    m.destination = i % 3 == 0 ? kBroadcast : (i + 1) % robots;
    m.port = static_cast<std::uint16_t>(i * 7919);
    m.payload.assign(std::size_t{i} * 10, static_cast<std::byte>(i));
    batch.messages.push_back(std::move(m));
  }
  return batch;
}

// Both ends as after a handshake for `robots` robots (the limits every count is checked against).
void shake_hands(StepChannel& robot, StepChannel& network, std::uint32_t robots) {
  const Welcome welcome{1, robots, 100'000'000};
  robot.fix_limits(welcome);
  network.fix_limits(welcome);
}

TEST(StepChannel, BatchRoundTripsAcrossChunks) {
  InprocChannel link(std::uint64_t{1} << 20);
  StepChannel robot(link.robot_end(), "the network half");
  StepChannel network(link.network_end(), "the robot half");
  shake_hands(robot, network, 2500);
  const StepBatch sent = sample_batch(2500, 20);  // three positions records
  ASSERT_TRUE(robot.send_batch(sent).ok());
  StepBatch got;
  bool finished = true;
  const auto r = network.receive_batch(got, finished);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_FALSE(finished);
  EXPECT_EQ(got.step, sent.step);
  EXPECT_EQ(got.start, sent.start);
  ASSERT_EQ(got.positions.size(), sent.positions.size());
  for (std::size_t i = 0; i < sent.positions.size(); ++i)
    EXPECT_EQ(got.positions[i], sent.positions[i]);
  ASSERT_EQ(got.messages.size(), sent.messages.size());
  for (std::size_t i = 0; i < sent.messages.size(); ++i) {
    EXPECT_EQ(got.messages[i].message_id, sent.messages[i].message_id);
    EXPECT_EQ(got.messages[i].source, sent.messages[i].source);
    EXPECT_EQ(got.messages[i].destination, sent.messages[i].destination);
    EXPECT_EQ(got.messages[i].port, sent.messages[i].port);
    EXPECT_EQ(got.messages[i].payload, sent.messages[i].payload);
  }
  ASSERT_TRUE(robot.send_finish().ok());
  ASSERT_TRUE(network.receive_batch(got, finished).ok());
  EXPECT_TRUE(finished);
}

TEST(StepChannel, ResultAndReportRoundTrip) {
  InprocChannel link(std::uint64_t{1} << 16);
  StepChannel robot(link.robot_end(), "the network half");
  StepChannel network(link.network_end(), "the robot half");
  // The robot half sent five unicast messages, so five deliveries may come back.
  shake_hands(robot, network, 10);
  StepBatch batch = sample_batch(10, 0);
  for (std::uint32_t i = 0; i < 5; ++i) batch.messages.push_back({i, 1, 2, {}});
  ASSERT_TRUE(robot.send_batch(batch).ok());
  bool finished = false;
  ASSERT_TRUE(network.receive_batch(batch, finished).ok());
  StepResult sent;
  sent.step = 3;
  sent.events = 12345;
  for (std::uint32_t i = 0; i < 5; ++i) {
    Delivery d;
    d.message_id = i;
    d.source = 1;
    d.destination = i == 0 ? kBroadcast : 2;
    d.receiver = 2 + i;
    d.sent_at = SimTime{1000 + i};
    d.delivered_at = SimTime{5000 + i};
    d.hops = i + 1;
    d.port = static_cast<std::uint16_t>(65535 - i);
    d.payload.assign(i, std::byte{0x5a});
    sent.deliveries.push_back(d);
  }
  ASSERT_TRUE(network.send_result(sent).ok());
  StepResult got;
  const auto r = robot.receive_result(got);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(got.step, 3U);
  EXPECT_EQ(got.events, 12345U);
  ASSERT_EQ(got.deliveries.size(), 5U);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(got.deliveries[i].receiver, sent.deliveries[i].receiver);
    EXPECT_EQ(got.deliveries[i].destination, sent.deliveries[i].destination);
    EXPECT_EQ(got.deliveries[i].delivered_at, sent.deliveries[i].delivered_at);
    EXPECT_EQ(got.deliveries[i].hops, sent.deliveries[i].hops);
    EXPECT_EQ(got.deliveries[i].port, sent.deliveries[i].port);
    EXPECT_EQ(got.deliveries[i].payload, sent.deliveries[i].payload);
  }
  NetworkReport report;
  report.sent = 10;
  report.delivered = 5;
  report.dropped = {{"no_route", 2}, {"queue_full", 0}};
  report.pdr = 0.5;
  report.delay_mean_s = 0.25;
  report.hops_mean = 1.5;
  report.mac = {{"tx_frames", 40}, {"acks", 7}};
  report.routing = {{"control_packets", 3}};
  report.events = 12345;
  report.network_cpu_s = 0.75;
  ASSERT_TRUE(network.send_report(report).ok());
  NetworkReport received;
  ASSERT_TRUE(robot.receive_report(received).ok());
  EXPECT_EQ(received, report);
  EXPECT_FALSE(received.delay_p50_s.has_value());
}

TEST(StepChannel, AReportWithImpossiblyManyCountersIsMalformed) {
  WaitPolicy impatient;
  impatient.timeout = std::chrono::seconds(5);
  InprocChannel link(std::uint64_t{1} << 16, impatient);
  StepChannel robot(link.robot_end(), "the network half");
  // type, sent, delivered, then a dropped-list length far beyond any report's.
  ASSERT_EQ(link.network_end().send(encode(RecordType::report, std::uint64_t{1}, std::uint64_t{1},
                                           std::uint32_t{0xFFFFFFFF})),
            IoStatus::ok);
  ASSERT_EQ(link.network_end().flush(), IoStatus::ok);
  NetworkReport received;
  const ProtocolResult r = robot.receive_report(received);
  EXPECT_EQ(r.io, IoStatus::corrupt);
  EXPECT_NE(r.error.find("malformed report record"), std::string::npos) << r.error;
}

TEST(StepChannel, MalformedRecordsAreNamed) {
  WaitPolicy impatient;
  impatient.timeout = std::chrono::seconds(5);  // a mistake here fails fast instead of hanging
  InprocChannel link(std::uint64_t{1} << 16, impatient);
  StepChannel network(link.network_end(), "the robot half");
  ASSERT_EQ(link.robot_end().send(encode(std::uint32_t{99})), IoStatus::ok);
  ASSERT_EQ(link.robot_end().flush(), IoStatus::ok);
  StepBatch batch;
  bool finished = false;
  auto r = network.receive_batch(batch, finished);
  EXPECT_EQ(r.io, IoStatus::corrupt);
  EXPECT_NE(r.error.find("unknown record type 99"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("the robot half"), std::string::npos) << r.error;

  // A step_begin that is too short.
  ASSERT_EQ(link.robot_end().send(encode(RecordType::step_begin, std::uint64_t{1})), IoStatus::ok);
  ASSERT_EQ(link.robot_end().flush(), IoStatus::ok);
  r = network.receive_batch(batch, finished);
  EXPECT_NE(r.error.find("malformed step_begin record"), std::string::npos) << r.error;

  // A delivery where a step_begin is due.
  ASSERT_EQ(link.robot_end().send(encode(RecordType::delivery)), IoStatus::ok);
  ASSERT_EQ(link.robot_end().flush(), IoStatus::ok);
  r = network.receive_batch(batch, finished);
  EXPECT_NE(r.error.find("sent a delivery record where step_begin or finish was expected"),
            std::string::npos)
      << r.error;
}

TEST(StepChannel, PeerFailureAndCloseAreExplained) {
  InprocChannel link(std::uint64_t{1} << 16);
  StepChannel robot(link.robot_end(), "the network half");
  StepChannel network(link.network_end(), "the robot half");
  network.send_failure("plugin 'flooding' threw: out of memory");
  link.network_end().close();
  StepResult result;
  auto r = robot.receive_result(result);
  EXPECT_EQ(r.error, "the network half failed: plugin 'flooding' threw: out of memory");
  r = robot.receive_result(result);
  EXPECT_EQ(r.io, IoStatus::closed);
  EXPECT_NE(r.error.find("lost the network half"), std::string::npos) << r.error;
  // The network end stopped consuming: sending to it fails at once instead of filling the ring.
  EXPECT_EQ(robot.send_batch(sample_batch(3, 1)).io, IoStatus::closed);
}

Hello sample_hello() {
  Hello hello;
  hello.scenario_yaml = "name: x\n";
  hello.run_dir = "/tmp/run";
  return hello;
}

constexpr Welcome kSampleWelcome{9, 40, 100'000'000};

// The hello carries one description of the run, the scenario; the welcome says what the network
// half made of it, and both ends then hold the limits it implies.
TEST(StepChannel, HandshakeCarriesTheScenarioAndTheWelcomeFixesTheLimits) {
  InprocChannel link(std::uint64_t{1} << 16);
  StepChannel robot(link.robot_end(), "the network half");
  StepChannel network(link.network_end(), "the robot half");
  ASSERT_TRUE(robot.send_hello(sample_hello()).ok());
  Hello got;
  ASSERT_TRUE(network.receive_hello(got).ok());
  EXPECT_EQ(got.scenario_yaml, "name: x\n");
  EXPECT_EQ(got.run_dir, "/tmp/run");
  ASSERT_TRUE(network.send_welcome(kSampleWelcome).ok());
  const auto r = robot.receive_welcome(kSampleWelcome);
  EXPECT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(robot.limits().robots, 40U);
  EXPECT_EQ(network.limits().robots, 40U);
}

TEST(StepChannel, ARecordLongerThanTheRingTakesIsAClearError) {
  InprocChannel link(std::uint64_t{1} << 16);  // records up to 30 KiB
  StepChannel robot(link.robot_end(), "the network half");
  Hello hello = sample_hello();
  hello.scenario_yaml.assign(40'000, 'x');
  const auto r = robot.send_hello(hello);
  EXPECT_EQ(r.io, IoStatus::too_large);
  EXPECT_EQ(r.error, "cannot send hello to the network half: record too long for the channel");
  // Nothing half-written reached the other end; the channel still works.
  hello.scenario_yaml = "name: x\n";
  ASSERT_TRUE(robot.send_hello(hello).ok());
  StepChannel network(link.network_end(), "the robot half");
  Hello got;
  ASSERT_TRUE(network.receive_hello(got).ok());
  EXPECT_EQ(got.scenario_yaml, "name: x\n");
}

TEST(StepChannel, ProtocolVersionMismatchNamesBothVersions) {
  InprocChannel link(std::uint64_t{1} << 16);
  StepChannel robot(link.robot_end(), "the network half");
  StepChannel network(link.network_end(), "the robot half");
  Hello sent = sample_hello();
  sent.protocol_version = kStepProtocolVersion + 1;
  ASSERT_TRUE(robot.send_hello(sent).ok());
  Hello got;
  const auto r = network.receive_hello(got);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("protocol version mismatch: the robot half speaks step protocol version " +
                         std::to_string(kStepProtocolVersion + 1) + ", this one speaks version " +
                         std::to_string(kStepProtocolVersion)),
            std::string::npos)
      << r.error;
}

TEST(StepChannel, WelcomeThatDisagreesIsRefused) {
  InprocChannel link(std::uint64_t{1} << 16);
  StepChannel robot(link.robot_end(), "the network half");
  StepChannel network(link.network_end(), "the robot half");
  Welcome other = kSampleWelcome;
  other.robots = 41;
  ASSERT_TRUE(network.send_welcome(other).ok());
  const auto r = robot.receive_welcome(kSampleWelcome);
  EXPECT_NE(r.error.find("handshake mismatch"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace swarmnet

namespace swarmnet {
namespace {

// Counts read from the peer are checked against what the handshake fixed before anything is
// allocated for them (issue 12, part 2).
class StepChannelBounds : public ::testing::Test {
 protected:
  StepChannelBounds() : link_(std::uint64_t{1} << 16, impatient()) {}
  static WaitPolicy impatient() {
    WaitPolicy policy;
    policy.timeout = std::chrono::seconds(5);
    return policy;
  }
  void feed(const std::vector<std::byte>& record) {
    ASSERT_EQ(link_.robot_end().send(record), IoStatus::ok);
    ASSERT_EQ(link_.robot_end().flush(), IoStatus::ok);
  }
  InprocChannel link_;
  StepChannel network_{link_.network_end(), "the robot half"};
  StepChannel robot_{link_.robot_end(), "the network half"};
};

TEST_F(StepChannelBounds, AStepBeginAnnouncingMillionsOfMessagesIsRefusedBeforeAllocating) {
  network_.fix_limits(Welcome{1, 10, 100'000'000});
  feed(encode(RecordType::step_begin, std::uint64_t{0}, std::int64_t{0}, std::uint32_t{10},
              std::uint32_t{25'000'000}));
  StepBatch batch;
  bool finished = false;
  const ProtocolResult r = network_.receive_batch(batch, finished);
  EXPECT_EQ(r.io, IoStatus::corrupt);
  EXPECT_NE(r.error.find("25000000 messages in step_begin; at most 640"), std::string::npos)
      << r.error;
  EXPECT_EQ(batch.messages.capacity(), 0U);
}

// A NaN or infinite position would index no cell of the channel's grid: refused with the robot.
TEST_F(StepChannelBounds, APositionThatIsNotAFiniteNumberIsRefused) {
  robot_.fix_limits(Welcome{1, 4, 100'000'000});
  network_.fix_limits(Welcome{1, 4, 100'000'000});
  StepBatch batch = sample_batch(4, 0);
  batch.positions[2] = Vec2(std::numeric_limits<double>::quiet_NaN(), 1.0);
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  StepBatch got;
  bool finished = false;
  const ProtocolResult r = network_.receive_batch(got, finished);
  EXPECT_EQ(r.io, IoStatus::corrupt);
  EXPECT_NE(r.error.find("a position that is not a finite number for robot 2"), std::string::npos)
      << r.error;
}

TEST_F(StepChannelBounds, AStepBeginWithAnotherSwarmSizeOrBeforeTheHandshakeIsRefused) {
  StepBatch batch;
  bool finished = false;
  feed(encode(RecordType::step_begin, std::uint64_t{0}, std::int64_t{0}, std::uint32_t{4},
              std::uint32_t{0}));
  ProtocolResult r = network_.receive_batch(batch, finished);
  EXPECT_NE(r.error.find("before the handshake"), std::string::npos) << r.error;
  network_.fix_limits(Welcome{1, 10, 100'000'000});
  feed(encode(RecordType::step_begin, std::uint64_t{0}, std::int64_t{0}, std::uint32_t{0xFFFFFFFF},
              std::uint32_t{0}));
  r = network_.receive_batch(batch, finished);
  EXPECT_NE(r.error.find("announced 4294967295 robots in step_begin; the handshake fixed 10"),
            std::string::npos)
      << r.error;
  EXPECT_EQ(batch.positions.capacity(), 0U);
}

// The swarm size comes from the scenario the network half validated (robots.count is at most
// kMaxRobots there); its welcome never fixes an impossible one.
TEST_F(StepChannelBounds, AWelcomeForAnImpossibleSwarmIsNeverSent) {
  const ProtocolResult r = network_.send_welcome(Welcome{1, 0xFFFFFFFF, 100'000'000});
  EXPECT_EQ(r.io, IoStatus::corrupt);
  EXPECT_NE(r.error.find("4294967295 robots"), std::string::npos) << r.error;
  EXPECT_EQ(network_.limits().robots, 0U);
}

TEST_F(StepChannelBounds, DeliveriesBeyondWhatTheSentMessagesCanProduceAreRefused) {
  robot_.fix_limits(Welcome{1, 4, 100'000'000});
  network_.fix_limits(Welcome{1, 4, 100'000'000});
  StepBatch batch = sample_batch(4, 0);
  batch.messages.push_back({1, 0, 2, {}});  // one unicast message: at most one delivery
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  bool finished = false;
  ASSERT_TRUE(network_.receive_batch(batch, finished).ok());
  StepResult result;
  for (int i = 0; i < 3; ++i) result.deliveries.push_back({1, 0, 2, 2, {}, {}, 1, {}});
  ASSERT_TRUE(network_.send_result(result).ok());
  StepResult got;
  const ProtocolResult r = robot_.receive_result(got);
  EXPECT_EQ(r.io, IoStatus::corrupt);
  EXPECT_NE(r.error.find("more deliveries than the messages it was given can produce"),
            std::string::npos)
      << r.error;
  EXPECT_LE(got.deliveries.size(), 1U);
}

// Step i starts at exactly i x the welcome's step, and steps come in order: a far start would
// have the network half simulate toward it for hours.
TEST_F(StepChannelBounds, AStepOutOfOrderOrStartingElsewhereIsRefusedBeforeItIsRead) {
  robot_.fix_limits(Welcome{1, 4, 100'000'000});
  network_.fix_limits(Welcome{1, 4, 100'000'000});
  StepBatch batch = sample_batch(4, 0);
  StepBatch got;
  bool finished = false;
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  ASSERT_TRUE(network_.receive_batch(got, finished).ok());  // step 0 at 0
  batch.step = 1;
  batch.start = SimTime{100'000'000};
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  ASSERT_TRUE(network_.receive_batch(got, finished).ok());  // step 1 at 0.1 s
  batch.step = 2;
  batch.start = SimTime{std::int64_t{1} << 62};
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  ProtocolResult r = network_.receive_batch(got, finished);
  EXPECT_EQ(r.io, IoStatus::corrupt);
  EXPECT_NE(r.error.find("said step 2 starts at 4611686018427387904 ns"), std::string::npos)
      << r.error;
}

TEST_F(StepChannelBounds, AStepNumberThatSkipsOrOverflowsIsRefused) {
  network_.fix_limits(Welcome{1, 4, 100'000'000});
  for (const std::uint64_t step : {std::uint64_t{3}, ~std::uint64_t{0}}) {
    feed(encode(RecordType::step_begin, step, std::int64_t{0}, std::uint32_t{4}, std::uint32_t{0}));
    StepBatch batch;
    bool finished = false;
    const ProtocolResult r = network_.receive_batch(batch, finished);
    EXPECT_EQ(r.io, IoStatus::corrupt);
    EXPECT_NE(r.error.find("where step 0 was due"), std::string::npos) << r.error;
  }
}

// network.neighbors: each robot's table crosses with the step's result and is checked against
// the handshake's max_neighbors like every other count.
TEST_F(StepChannelBounds, NeighborTablesRoundTripAndAreCheckedAgainstTheHandshake) {
  const Welcome welcome{1, 4, 100'000'000, 2};
  robot_.fix_limits(welcome);
  network_.fix_limits(welcome);
  StepResult sent;
  sent.neighbor_counts = {2, 0, 1, 0};
  sent.neighbors = {{1, SimTime{5}, -70.0, -71.0, 20.0, 3, 4, 2},
                    {3, SimTime{6}, -80.0, -79.5, 10.0, 1, 0, 0},
                    {0, SimTime{7}, -60.0, -60.0, 30.0, 2, 1, 1}};
  ASSERT_TRUE(network_.send_result(sent).ok());
  StepResult got;
  ASSERT_TRUE(robot_.receive_result(got).ok());
  EXPECT_EQ(got.neighbor_counts, sent.neighbor_counts);
  ASSERT_EQ(got.neighbors.size(), 3U);
  EXPECT_EQ(got.neighbors[1].id, 3U);
  EXPECT_EQ(got.neighbors[1].last_heard, SimTime{6});
  EXPECT_EQ(got.neighbors[1].rssi_smoothed_dbm, -79.5);
  EXPECT_EQ(got.neighbors[2].frames, 2U);
  EXPECT_EQ(got.neighbors[0].unicasts, 4U);
  EXPECT_EQ(got.neighbors[0].first_attempt_acks, 2U);

  // More entries than the handshake allows, an entry naming the robot itself, a table for a
  // robot outside the swarm, more first-attempt acknowledgements than unicasts: each refused
  // with the bound named.
  for (const auto& [robot, ids] :
       {std::pair<std::uint32_t, std::vector<std::uint32_t>>{0, {1, 2, 3}},
        std::pair<std::uint32_t, std::vector<std::uint32_t>>{1, {1}},
        std::pair<std::uint32_t, std::vector<std::uint32_t>>{9, {1}},
        std::pair<std::uint32_t, std::vector<std::uint32_t>>{0, {kNoNode}}}) {
    std::vector<std::byte> record =
        encode(RecordType::neighbors, robot, static_cast<std::uint32_t>(ids.size()));
    for (const std::uint32_t id : ids) {
      const bool too_many_acks = id == kNoNode;
      const auto entry =
          encode(too_many_acks ? 1U : id, std::int64_t{1}, -70.0, -70.0, 20.0, std::uint32_t{1},
                 std::uint32_t{1}, std::uint32_t{too_many_acks ? 2U : 1U});
      record.insert(record.end(), entry.begin(), entry.end());
    }
    ASSERT_EQ(link_.network_end().send(record), IoStatus::ok);
    ASSERT_EQ(link_.network_end().flush(), IoStatus::ok);
    const ProtocolResult r = robot_.receive_result(got);
    EXPECT_EQ(r.io, IoStatus::corrupt);
    EXPECT_NE(r.error.find("neighbour table"), std::string::npos) << r.error;
  }
}

TEST_F(StepChannelBounds, ANeighborTableNobodyAskedForIsRefused) {
  robot_.fix_limits(Welcome{1, 4, 100'000'000});
  const auto record = encode(RecordType::neighbors, std::uint32_t{0}, std::uint32_t{0});
  ASSERT_EQ(link_.network_end().send(record), IoStatus::ok);
  ASSERT_EQ(link_.network_end().flush(), IoStatus::ok);
  StepResult got;
  const ProtocolResult r = robot_.receive_result(got);
  EXPECT_NE(r.error.find("sent a neighbour table nobody asked for"), std::string::npos) << r.error;
}

// Send options ride in message records; reports come back once per message that asked, to the
// robot and port that sent it, and any other report is refused.
TEST_F(StepChannelBounds, SendOptionsAndReportsRoundTripAndOnlyOwedReportsAreTaken) {
  const Welcome welcome{1, 4, 100'000'000};
  robot_.fix_limits(welcome);
  network_.fix_limits(welcome);
  StepBatch batch = sample_batch(4, 3);
  batch.messages[0].hop_limit = 1;
  batch.messages[1].report = true;
  batch.messages[2].hop_limit = 255;
  batch.messages[2].report = true;
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  StepBatch got;
  bool finished = true;
  ASSERT_TRUE(network_.receive_batch(got, finished).ok());
  ASSERT_EQ(got.messages.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(got.messages[i].hop_limit, batch.messages[i].hop_limit) << i;
    EXPECT_EQ(got.messages[i].report, batch.messages[i].report) << i;
  }

  StepResult result;
  result.step = 0;
  AddressedSendReport ack{batch.messages[1].source, batch.messages[1].port, {}};
  ack.report = {batch.messages[1].message_id,
                SendOutcome::acknowledged,
                DropReason::no_route,
                SimTime{12345},
                2,
                3};
  AddressedSendReport drop{batch.messages[2].source, batch.messages[2].port, {}};
  drop.report = {batch.messages[2].message_id,
                 SendOutcome::dropped,
                 DropReason::arp_unresolved,
                 SimTime{99},
                 kNoNode,
                 0};
  result.send_reports = {ack, drop};
  ASSERT_TRUE(network_.send_result(result).ok());
  StepResult back;
  const ProtocolResult r = robot_.receive_result(back);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(back.send_reports.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& a = back.send_reports[i];
    const auto& b = result.send_reports[i];
    EXPECT_EQ(a.source, b.source);
    EXPECT_EQ(a.port, b.port);
    EXPECT_EQ(a.report.message_id, b.report.message_id);
    EXPECT_EQ(a.report.outcome, b.report.outcome);
    EXPECT_EQ(a.report.reason, b.report.reason);
    EXPECT_EQ(a.report.at, b.report.at);
    EXPECT_EQ(a.report.next_hop, b.report.next_hop);
    EXPECT_EQ(a.report.attempts, b.report.attempts);
  }

  // The same report again, one for a message that asked for none, one from another port.
  AddressedSendReport stray = ack;
  stray.report.message_id = batch.messages[0].message_id;
  stray.source = batch.messages[0].source;
  stray.port = batch.messages[0].port;
  for (const AddressedSendReport* bad_report : {&ack, &stray}) {
    const AddressedSendReport& bad = *bad_report;
    // Each on a channel of its own: a refusal leaves the rest of its result unread.
    InprocChannel link(std::uint64_t{1} << 16, impatient());
    StepChannel robot(link.robot_end(), "the network half");
    StepChannel network(link.network_end(), "the robot half");
    shake_hands(robot, network, 4);
    ASSERT_TRUE(robot.send_batch(batch).ok());
    ASSERT_TRUE(network.receive_batch(got, finished).ok());
    if (bad_report == &ack) {  // reported once already
      result.send_reports = {ack};
      ASSERT_TRUE(network.send_result(result).ok());
      ASSERT_TRUE(robot.receive_result(back).ok());
    }
    result.send_reports = {bad};
    ASSERT_TRUE(network.send_result(result).ok());
    const ProtocolResult refused = robot.receive_result(back);
    EXPECT_EQ(refused.io, IoStatus::corrupt);
    EXPECT_NE(refused.error.find("which asked for none there or was reported already"),
              std::string::npos)
        << refused.error;
  }
}

TEST_F(StepChannelBounds, AReportWithAnOutcomeOrReasonOutOfRangeIsMalformed) {
  const Welcome welcome{1, 4, 100'000'000};
  robot_.fix_limits(welcome);
  network_.fix_limits(welcome);
  StepBatch batch = sample_batch(4, 1);
  batch.messages[0].report = true;
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  const AppMessage& m = batch.messages[0];
  for (const auto [outcome, reason] : {std::pair<std::uint8_t, std::uint8_t>{3, 0}, {2, 7}}) {
    const auto record = encode(RecordType::send_report, m.message_id, m.source, m.port, outcome,
                               reason, std::int64_t{0}, kNoNode, std::uint32_t{0});
    ASSERT_EQ(link_.network_end().send(record), IoStatus::ok);
    ASSERT_EQ(link_.network_end().flush(), IoStatus::ok);
    StepResult got;
    const ProtocolResult r = robot_.receive_result(got);
    EXPECT_NE(r.error.find("malformed send_report record"), std::string::npos) << r.error;
  }
}

// Route queries go with the batch, one record per robot; the result answers exactly the step's
// queries, in order, and anything else is refused.
TEST_F(StepChannelBounds, RouteQueriesAndAnswersRoundTripAndOnlyTheStepsQueriesAreAnswered) {
  const Welcome welcome{1, 4, 100'000'000};
  robot_.fix_limits(welcome);
  network_.fix_limits(welcome);
  StepBatch batch = sample_batch(4, 1);
  batch.route_queries = {{0, 1}, {0, 3}, {2, 0}};
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  StepBatch got;
  bool finished = true;
  ASSERT_TRUE(network_.receive_batch(got, finished).ok());
  EXPECT_EQ(got.route_queries, batch.route_queries);
  EXPECT_EQ(got.messages.size(), 1U);

  StepResult result;
  result.step = 0;
  result.routes = {{{0, 1}, {RouteStatus::valid, 1, 1, SimTime{100}}},
                   {{0, 3}, {RouteStatus::valid, 1, 3, SimTime{100}}},
                   {{2, 0}, {RouteStatus::none, kNoNode, 0, SimTime{100}}}};
  ASSERT_TRUE(network_.send_result(result).ok());
  StepResult back;
  const ProtocolResult r = robot_.receive_result(back);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(back.routes.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.routes[i].query, result.routes[i].query);
    EXPECT_EQ(back.routes[i].route.status, result.routes[i].route.status);
    EXPECT_EQ(back.routes[i].route.next_hop, result.routes[i].route.next_hop);
    EXPECT_EQ(back.routes[i].route.hops, result.routes[i].route.hops);
    EXPECT_EQ(back.routes[i].route.as_of, SimTime{100});
  }

  // Step 1 asks nothing: an answer in its result is refused.
  batch.step = 1;
  batch.start = SimTime{100'000'000};
  batch.route_queries.clear();
  ASSERT_TRUE(robot_.send_batch(batch).ok());
  ASSERT_TRUE(network_.receive_batch(got, finished).ok());
  EXPECT_TRUE(got.route_queries.empty());
  result.step = 1;
  result.routes.resize(1);
  ASSERT_TRUE(network_.send_result(result).ok());
  const ProtocolResult refused = robot_.receive_result(back);
  EXPECT_EQ(refused.io, IoStatus::corrupt);
  EXPECT_NE(refused.error.find("answered 1 route queries in step 1, which asked 0"),
            std::string::npos)
      << refused.error;
}

TEST_F(StepChannelBounds, RouteQueriesNamingNoOtherRobotOrOutOfOrderAreRefused) {
  network_.fix_limits(Welcome{1, 4, 100'000'000});
  const std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> bad = {
      {1, {1}},     // itself
      {0, {3, 2}},  // descending
      {0, {4}},     // outside the swarm
      {7, {0}},     // from outside the swarm
      {0, {}},      // an empty record
  };
  for (const auto& [robot, destinations] : bad) {
    InprocChannel link(std::uint64_t{1} << 16, impatient());
    StepChannel network(link.network_end(), "the robot half");
    network.fix_limits(Welcome{1, 4, 100'000'000});
    std::vector<std::vector<std::byte>> records;
    records.push_back(encode(RecordType::step_begin, std::uint64_t{0}, std::int64_t{0},
                             std::uint32_t{4}, std::uint32_t{0}));
    std::vector<std::byte> positions =
        encode(RecordType::positions, std::uint32_t{0}, std::uint32_t{4});
    for (int i = 0; i < 8; ++i) {
      const auto coordinate = encode(1.0);
      positions.insert(positions.end(), coordinate.begin(), coordinate.end());
    }
    records.push_back(positions);
    std::vector<std::byte> query =
        encode(RecordType::route_query, robot, static_cast<std::uint32_t>(destinations.size()));
    for (const std::uint32_t d : destinations) {
      const auto entry = encode(d);
      query.insert(query.end(), entry.begin(), entry.end());
    }
    records.push_back(query);
    for (const auto& record : records) ASSERT_EQ(link.robot_end().send(record), IoStatus::ok);
    ASSERT_EQ(link.robot_end().flush(), IoStatus::ok);
    StepBatch got;
    bool finished = false;
    const ProtocolResult r = network.receive_batch(got, finished);
    EXPECT_EQ(r.io, IoStatus::corrupt) << robot;
    EXPECT_NE(r.error.find("route quer"), std::string::npos) << r.error;
  }
}

TEST_F(StepChannelBounds, ARouteAnswerNoProtocolCanGiveIsRefused) {
  const Welcome welcome{1, 4, 100'000'000};
  struct Bad {
    std::uint8_t status;
    std::uint32_t next_hop;
    std::uint32_t hops;
  };
  for (const Bad bad : {Bad{0, kNoNode, 0},  // pending is the robot half's own
                        Bad{3, 9, 1},        // a next hop outside the swarm
                        Bad{3, 1, 0},        // a valid route of no hops
                        Bad{4, 1, 1}}) {     // no such status
    InprocChannel link(std::uint64_t{1} << 16, impatient());
    StepChannel robot(link.robot_end(), "the network half");
    StepChannel network(link.network_end(), "the robot half");
    robot.fix_limits(welcome);
    network.fix_limits(welcome);
    StepBatch batch = sample_batch(4, 0);
    batch.route_queries = {{0, 2}};
    ASSERT_TRUE(robot.send_batch(batch).ok());
    const auto record =
        encode(RecordType::route, std::uint32_t{0}, std::uint32_t{1}, std::uint32_t{2}, bad.status,
               bad.next_hop, bad.hops, std::int64_t{0});
    ASSERT_EQ(link.network_end().send(record), IoStatus::ok);
    ASSERT_EQ(link.network_end().flush(), IoStatus::ok);
    StepResult got;
    const ProtocolResult r = robot.receive_result(got);
    EXPECT_EQ(r.io, IoStatus::corrupt);
    EXPECT_NE(r.error.find("route answer for robot 0 about 2"), std::string::npos) << r.error;
  }
}

}  // namespace
}  // namespace swarmnet
