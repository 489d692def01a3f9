// The ns-3 network engine's model (core/src/ns3_engine/), driven as the kernel drives it:
// window by window through the Network interface. Nodes are 802.11a at 6 Mbps with log-distance
// loss (exponent 3, 46.6777 dB at 1 m, 27.05 dBm): a frame is detected up to about 120 m.
#include "ns3_engine/ns3_network.hpp"

#include <gtest/gtest.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/simulator.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "ns3_engine/finite_power_guard.hpp"

namespace swarmnet::ns3engine {
namespace {

constexpr std::int64_t kMs = 1'000'000;
constexpr std::int64_t kS = 1'000'000'000;

Config line_config(std::uint32_t nodes, Routing routing) {
  Config config;
  config.nodes = nodes;
  config.run = 1;
  config.standard = "80211a";
  config.loss_chain = {
      {"ns3::LogDistancePropagationLossModel",
       {{"Exponent", "3"}, {"ReferenceDistance", "1"}, {"ReferenceLoss", "46.6777"}}}};
  config.phy = {{"TxPowerStart", "27.0531"}, {"TxPowerEnd", "27.0531"}, {"TxPowerLevels", "1"},
                {"RxSensitivity", "-101"},   {"CcaEdThreshold", "-62"}, {"RxNoiseFigure", "7"}};
  config.preamble_detection = {{"MinimumRssi", "-82"}, {"Threshold", "4"}};
  config.rate_manager = {"ns3::ConstantRateWifiManager",
                         {{"DataMode", "OfdmRate6Mbps"}, {"ControlMode", "OfdmRate6Mbps"}}};
  config.routing = routing;
  return config;
}

// Node i at (spacing_m * i, 0).
std::vector<double> line(std::uint32_t nodes, double spacing_m) {
  std::vector<double> xy;
  for (std::uint32_t i = 0; i < nodes; ++i) {
    xy.push_back(spacing_m * i);
    xy.push_back(0.0);
  }
  return xy;
}

Message message(std::uint64_t id, std::uint32_t source, std::uint32_t destination,
                std::int64_t inject_ns, std::size_t payload_bytes = 100) {
  Message m;
  m.message_id = id;
  m.source = source;
  m.destination = destination;
  m.port = 7;
  m.inject_ns = inject_ns;
  m.payload.resize(payload_bytes);
  for (std::size_t i = 0; i < payload_bytes; ++i) m.payload[i] = static_cast<std::uint8_t>(i);
  return m;
}

std::uint64_t count(const Counters& counters, const std::string& name) {
  for (const auto& [key, value] : counters) {
    if (key == name) return value;
  }
  ADD_FAILURE() << "no counter " << name;
  return 0;
}

std::vector<std::string> names(const Counters& counters) {
  std::vector<std::string> out;
  for (const auto& entry : counters) out.push_back(entry.first);
  return out;
}

// Runs one window to `end_ns` and returns what arrived in it.
std::vector<Arrival> run(Network& network, std::int64_t end_ns, const std::vector<double>& xy,
                         const std::vector<Message>& messages = {}) {
  std::vector<Arrival> arrivals;
  network.run_window(end_ns, xy, messages, arrivals);
  return arrivals;
}

void expect_same(const Report& a, const Report& b) {
  EXPECT_EQ(a.mac, b.mac);
  EXPECT_EQ(a.routing, b.routing);
  EXPECT_EQ(a.drops, b.drops);
  EXPECT_EQ(a.events, b.events);
}

bool same_arrivals(const std::vector<Arrival>& a, const std::vector<Arrival>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].message_id != b[i].message_id || a[i].receiver != b[i].receiver ||
        a[i].arrived_ns != b[i].arrived_ns || a[i].hops != b[i].hops) {
      return false;
    }
  }
  return true;
}

TEST(Ns3Network, ReportsCountersInTheirFixedOrder) {
  Ns3Network network(line_config(2, Routing::aodv));
  const Report report = network.report();
  EXPECT_EQ(names(report.mac),
            (std::vector<std::string>{"tx_frames", "tx_bytes", "data_frames", "ack_frames", "rts",
                                      "cts", "retries", "collisions", "rx_drops", "arp_requests",
                                      "arp_replies", "arp_drops"}));
  EXPECT_EQ(names(report.routing),
            (std::vector<std::string>{"control_packets", "control_bytes", "data_forwards", "rreq",
                                      "rrep", "hello", "rerr", "rrep_ack"}));
  EXPECT_EQ(names(report.drops),
            (std::vector<std::string>{"no_route", "queue_full", "ttl_expired", "retry_limit",
                                      "buffer_timeout", "arp_queue_full", "arp_unresolved"}));
}

TEST(Ns3Network, DirectUnicastArrivesAfterItsAirtime) {
  const std::vector<double> xy = line(2, 50.0);
  std::uint64_t tx_bytes[2] = {};
  for (const std::size_t payload : {std::size_t{100}, std::size_t{0}}) {
    Ns3Network network(line_config(2, Routing::direct));
    const std::vector<Arrival> arrivals =
        run(network, 100 * kMs, xy, {message(7, 0, 1, 1 * kMs, payload)});
    ASSERT_EQ(arrivals.size(), 1U) << "payload " << payload;
    EXPECT_EQ(arrivals[0].message_id, 7U);
    EXPECT_EQ(arrivals[0].receiver, 1U);
    EXPECT_EQ(arrivals[0].hops, 1U);
    // 6 Mbit/s OFDM: 20 us of preamble and header, then 4 us per 24 bits of a 64-byte-larger
    // MPDU (UDP, IP, LLC, MAC header, FCS); ARP runs first.
    const std::int64_t airtime_ns = 20'000 + 4'000 * ((16 + 8 * (payload + 64) + 6 + 23) / 24);
    EXPECT_GE(arrivals[0].arrived_ns, 1 * kMs + airtime_ns);
    EXPECT_LT(arrivals[0].arrived_ns, 100 * kMs);
    const Report report = network.report();
    EXPECT_EQ(count(report.mac, "arp_requests"), 1U);
    EXPECT_EQ(count(report.mac, "arp_replies"), 1U);
    EXPECT_EQ(count(report.mac, "data_frames"), 3U);  // ARP request, ARP reply, the message
    EXPECT_EQ(count(report.mac, "ack_frames"), 2U);
    EXPECT_EQ(count(report.mac, "retries"), 0U);
    EXPECT_GT(report.events, 0U);
    tx_bytes[payload == 0 ? 1 : 0] = count(report.mac, "tx_bytes");
  }
  // The payload is carried byte for byte: the runs differ by its size alone.
  EXPECT_EQ(tx_bytes[0] - tx_bytes[1], 100U);
}

TEST(Ns3Network, BroadcastReachesTheOtherNodeOnly) {
  Ns3Network network(line_config(2, Routing::direct));
  const std::vector<Arrival> arrivals =
      run(network, 50 * kMs, line(2, 50.0), {message(3, 1, kBroadcastNode, 2 * kMs, 20)});
  ASSERT_EQ(arrivals.size(), 1U);
  EXPECT_EQ(arrivals[0].message_id, 3U);
  EXPECT_EQ(arrivals[0].receiver, 0U);
  EXPECT_EQ(arrivals[0].hops, 1U);
  const Report report = network.report();
  EXPECT_EQ(count(report.mac, "data_frames"), 1U);  // no ARP for a broadcast
  EXPECT_EQ(count(report.mac, "ack_frames"), 0U);
}

TEST(Ns3Network, NothingArrivesOutOfRange) {
  Ns3Network network(line_config(2, Routing::direct));
  const std::vector<double> far = line(2, 500.0);
  EXPECT_TRUE(run(network, 1 * kS, far,
                  {message(1, 0, kBroadcastNode, 10 * kMs), message(2, 0, 1, 20 * kMs)})
                  .empty());
  const Report sent = network.report();
  EXPECT_EQ(count(sent.mac, "tx_frames"), 2U);  // the broadcast, the first ARP request
  EXPECT_EQ(count(sent.mac, "arp_requests"), 1U);
  // ARP asks three more times, a second apart, then drops the message waiting for it.
  EXPECT_TRUE(run(network, 6 * kS, far).empty());
  const Report dropped = network.report();
  EXPECT_EQ(count(dropped.mac, "arp_requests"), 4U);
  EXPECT_EQ(count(dropped.mac, "arp_replies"), 0U);
  EXPECT_EQ(count(dropped.mac, "arp_drops"), 1U);
  EXPECT_EQ(count(dropped.drops, "arp_unresolved"), 1U);
  EXPECT_EQ(count(dropped.drops, "retry_limit"), 0U);
  EXPECT_EQ(count(dropped.drops, "queue_full"), 0U);
}

TEST(Ns3Network, AodvCrossesALineInTwoHops) {
  Ns3Network network(line_config(3, Routing::aodv));
  const std::vector<double> xy = line(3, 100.0);
  EXPECT_TRUE(run(network, 1 * kS, xy).empty());  // hellos
  const std::vector<Arrival> arrivals = run(network, 3 * kS, xy, {message(11, 0, 2, 1 * kS + 123)});
  ASSERT_EQ(arrivals.size(), 1U);
  EXPECT_EQ(arrivals[0].message_id, 11U);
  EXPECT_EQ(arrivals[0].receiver, 2U);
  EXPECT_EQ(arrivals[0].hops, 2U);
  const Report report = network.report();
  EXPECT_EQ(count(report.routing, "data_forwards"), 1U);
  EXPECT_GE(count(report.routing, "rreq"), 1U);
  EXPECT_GE(count(report.routing, "rrep"), 1U);
  EXPECT_GT(count(report.routing, "hello"), 0U);
  EXPECT_EQ(count(report.routing, "control_packets"),
            count(report.routing, "rreq") + count(report.routing, "rrep") +
                count(report.routing, "hello") + count(report.routing, "rerr") +
                count(report.routing, "rrep_ack"));
  EXPECT_GT(count(report.routing, "control_bytes"), count(report.routing, "control_packets"));
  for (const auto& [name, value] : report.drops) EXPECT_EQ(value, 0U) << name;
}

TEST(Ns3Network, AodvGivesUpOnAnUnreachableDestination) {
  Ns3Network network(line_config(2, Routing::aodv));
  EXPECT_TRUE(run(network, 40 * kS, line(2, 500.0), {message(1, 0, 1, 100 * kMs)}).empty());
  const Report report = network.report();
  EXPECT_EQ(count(report.drops, "buffer_timeout"), 1U);
  EXPECT_GE(count(report.routing, "rreq"), 2U);
  EXPECT_EQ(count(report.routing, "rrep"), 0U);
}

TEST(Ns3Network, SimultaneousFramesCollide) {
  Ns3Network network(line_config(3, Routing::direct));
  // Nodes 0 and 2 send at the same instant on an idle channel: node 1, between them, receives
  // both at once and decodes neither.
  const std::vector<Arrival> arrivals =
      run(network, 50 * kMs, line(3, 50.0),
          {message(1, 0, kBroadcastNode, 5 * kMs), message(2, 2, kBroadcastNode, 5 * kMs)});
  for (const Arrival& arrival : arrivals) EXPECT_NE(arrival.receiver, 1U);
  const Report report = network.report();
  EXPECT_GE(count(report.mac, "collisions") + count(report.mac, "rx_drops"), 1U);
}

TEST(Ns3Network, FloodingRelaysAcrossALine) {
  Ns3Network network(line_config(3, Routing::flooding));
  const std::vector<double> xy = line(3, 100.0);
  const std::vector<Arrival> unicast = run(network, 1 * kS, xy, {message(5, 0, 2, 10 * kMs)});
  ASSERT_EQ(unicast.size(), 1U);
  EXPECT_EQ(unicast[0].receiver, 2U);
  EXPECT_EQ(unicast[0].hops, 2U);
  Report report = network.report();
  EXPECT_EQ(count(report.routing, "data_forwards"), 1U);  // node 1; the destination does not
  EXPECT_EQ(count(report.routing, "duplicates"), 1U);     // node 0 hears node 1's relay
  EXPECT_EQ(count(report.routing, "control_packets"), 0U);

  const std::vector<Arrival> broadcast =
      run(network, 2 * kS, xy, {message(6, 2, kBroadcastNode, 1 * kS + 5 * kMs)});
  ASSERT_EQ(broadcast.size(), 2U);  // every node but the source, in arrival order
  EXPECT_EQ(broadcast[0].receiver, 1U);
  EXPECT_EQ(broadcast[0].hops, 1U);
  EXPECT_EQ(broadcast[1].receiver, 0U);
  EXPECT_EQ(broadcast[1].hops, 2U);
  report = network.report();
  EXPECT_EQ(count(report.routing, "data_forwards"), 3U);  // nodes 1 and 0 relay the broadcast
}

TEST(Ns3Network, FloodingTtlBoundsTheHops) {
  Config config = line_config(3, Routing::flooding);
  config.flooding.ttl = 1;
  Ns3Network network(config);
  EXPECT_TRUE(run(network, 1 * kS, line(3, 100.0), {message(5, 0, 2, 10 * kMs)}).empty());
  const Report report = network.report();
  EXPECT_EQ(count(report.routing, "ttl_expired"), 1U);
  EXPECT_EQ(count(report.drops, "ttl_expired"), 1U);
  EXPECT_EQ(count(report.routing, "data_forwards"), 0U);
}

struct Outcome {
  std::vector<Arrival> arrivals;
  Report report;
};

// A line with traffic both ways and broadcasts, run in windows of `window_ns`.
Outcome line_traffic(std::int64_t window_ns, Routing routing = Routing::aodv) {
  Ns3Network network(line_config(3, routing));
  const std::vector<double> xy = line(3, 100.0);
  std::vector<Message> messages;
  for (std::uint64_t i = 0; i < 20; ++i) {
    const std::int64_t at = 500 * kMs + static_cast<std::int64_t>(i) * 37 * kMs + 4'321;
    messages.push_back(i % 3 == 0   ? message(i, 0, 2, at, 40 + i)
                       : i % 3 == 1 ? message(i, 2, 0, at, 40 + i)
                                    : message(i, 1, kBroadcastNode, at, 10));
  }
  Outcome outcome;
  for (std::int64_t start = 0; start < 2 * kS; start += window_ns) {
    std::vector<Message> in_window;
    for (const Message& m : messages) {
      if (m.inject_ns >= start && m.inject_ns < start + window_ns) in_window.push_back(m);
    }
    network.run_window(start + window_ns, xy, in_window, outcome.arrivals);
  }
  outcome.report = network.report();
  return outcome;
}

// Every random variable has its stream: a second network in the same process repeats the
// first exactly.
TEST(Ns3Network, IdenticalRunsGiveIdenticalResults) {
  for (const Routing routing :
       {Routing::direct, Routing::flooding, Routing::aodv, Routing::olsr, Routing::dsdv}) {
    const Outcome first = line_traffic(100 * kMs, routing);
    const Outcome second = line_traffic(100 * kMs, routing);
    EXPECT_GE(first.arrivals.size(), 10U) << static_cast<int>(routing);
    EXPECT_TRUE(same_arrivals(first.arrivals, second.arrivals)) << static_cast<int>(routing);
    expect_same(first.report, second.report);
  }
}

TEST(Ns3Network, ARunDependsOnItsRunNumber) {
  Config config = line_config(3, Routing::flooding);
  std::vector<Arrival> arrivals[2];
  for (const std::uint64_t run : {1U, 2U}) {
    config.run = run;
    Ns3Network network(config);
    arrivals[run - 1] =
        ::swarmnet::ns3engine::run(network, 1 * kS, line(3, 100.0), {message(1, 0, 2, 10 * kMs)});
  }
  ASSERT_EQ(arrivals[0].size(), 1U);
  ASSERT_EQ(arrivals[1].size(), 1U);
  EXPECT_NE(arrivals[0][0].arrived_ns, arrivals[1][0].arrived_ns);  // another relay jitter
}

// Windows only cut the run: every event before a window's end runs in it, and one at its end
// runs in the next, so 10 ms windows and 500 ms windows see the same network.
TEST(Ns3Network, WindowLengthDoesNotChangeTheRun) {
  const Outcome coarse = line_traffic(500 * kMs);
  const Outcome fine = line_traffic(10 * kMs);
  EXPECT_TRUE(same_arrivals(coarse.arrivals, fine.arrivals));
  expect_same(coarse.report, fine.report);
}

TEST(Ns3Network, AMessageAtAWindowsEndBelongsToTheNext) {
  Ns3Network network(line_config(2, Routing::direct));
  const std::vector<double> xy = line(2, 50.0);
  EXPECT_TRUE(run(network, 10 * kMs, xy).empty());
  // Injected at the first instant of the window [10 ms, 20 ms); arrivals are all before 20 ms.
  const std::vector<Arrival> arrivals =
      run(network, 20 * kMs, xy, {message(1, 0, kBroadcastNode, 10 * kMs)});
  ASSERT_EQ(arrivals.size(), 1U);
  EXPECT_GT(arrivals[0].arrived_ns, 10 * kMs);
  EXPECT_LT(arrivals[0].arrived_ns, 20 * kMs);
  // A frame still in the air at a window's end arrives in the next one.
  const std::int64_t end = 30 * kMs;
  EXPECT_TRUE(run(network, end, xy, {message(2, 0, kBroadcastNode, end - 10'000)}).empty());
  const std::vector<Arrival> later = run(network, 40 * kMs, xy);
  ASSERT_EQ(later.size(), 1U);
  EXPECT_GE(later[0].arrived_ns, end);
}

TEST(Ns3Network, MacQueueSettingsApply) {
  Config config = line_config(2, Routing::direct);
  config.mac_queue = {{"MaxSize", "2p"}};
  config.txop = {{"MinCw", "31"}, {"MaxCw", "1023"}};
  Ns3Network network(config);
  const std::vector<double> xy = line(2, 50.0);
  ASSERT_EQ(run(network, 100 * kMs, xy, {message(0, 0, 1, 1 * kMs)}).size(), 1U);  // ARP resolved
  std::vector<Message> burst;
  for (std::uint64_t i = 1; i <= 10; ++i) burst.push_back(message(i, 0, 1, 200 * kMs));
  const std::vector<Arrival> arrivals = run(network, 400 * kMs, xy, burst);
  EXPECT_LE(arrivals.size(), 3U);
  EXPECT_EQ(count(network.report().drops, "queue_full"), 10U - arrivals.size());
}

TEST(Ns3Network, OtherStandardsDeliver) {
  struct Case {
    const char* standard;
    const char* mode;
  };
  for (const Case& c : {Case{"80211b", "DsssRate1Mbps"}, Case{"80211g", "ErpOfdmRate6Mbps"},
                        Case{"80211n", "HtMcs0"}, Case{"80211ac", "VhtMcs0"}}) {
    Config config = line_config(2, Routing::direct);
    config.standard = c.standard;
    config.rate_manager.attributes = {{"DataMode", c.mode}, {"ControlMode", c.mode}};
    Ns3Network network(config);
    const std::vector<Arrival> arrivals =
        run(network, 100 * kMs, line(2, 20.0), {message(1, 0, 1, 1 * kMs)});
    ASSERT_EQ(arrivals.size(), 1U) << c.standard;
    EXPECT_EQ(arrivals[0].hops, 1U);
  }
}

// A proactive protocol on a 3-node line: after warm-up, 0 reaches 2 through 1. Returns the
// network's report.
Report expect_crosses_line_after_warm_up(const Config& config) {
  Ns3Network network(config);
  const std::vector<Arrival> arrivals =
      run(network, 10 * kS, line(3, 100.0), {message(1, 0, 2, 8 * kS + 77)});
  EXPECT_EQ(arrivals.size(), 1U);
  if (!arrivals.empty()) {
    EXPECT_EQ(arrivals[0].receiver, 2U);
    EXPECT_EQ(arrivals[0].hops, 2U);
  }
  const Report report = network.report();
  EXPECT_GT(count(report.routing, "control_packets"), 0U);
  return report;
}

TEST(Ns3Network, OlsrCrossesALineAfterWarmUp) {
  Config config = line_config(3, Routing::olsr);
  config.routing_attributes = {{"HelloInterval", "1s"}, {"TcInterval", "2s"}};
  const Report report = expect_crosses_line_after_warm_up(config);
  EXPECT_EQ(count(report.routing, "data_forwards"), 1U);
}

TEST(Ns3Network, DsdvCrossesALineAfterWarmUp) {
  Config config = line_config(3, Routing::dsdv);
  config.routing_attributes = {{"PeriodicUpdateInterval", "2s"}, {"SettlingTime", "1s"}};
  expect_crosses_line_after_warm_up(config);
}

TEST(Ns3Network, OlsrWithoutARouteCountsNoRoute) {
  Ns3Network network(line_config(3, Routing::olsr));
  // At once: OLSR has no route yet, and the UDP socket drops the datagram itself.
  EXPECT_TRUE(run(network, 10 * kMs, line(3, 100.0), {message(1, 0, 2, 1 * kMs)}).empty());
  EXPECT_EQ(count(network.report().drops, "no_route"), 1U);
}

// The message of the std::runtime_error that creating a network from `config` throws.
std::string creation_error(const Config& config) {
  try {
    Ns3Network network(config);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(Ns3Network, RefusesBadConfigurationsByName) {
  const Config good = line_config(2, Routing::aodv);
  const auto expect_refused = [](const Config& config, const std::vector<std::string>& parts) {
    const std::string what = creation_error(config);
    for (const std::string& part : parts) EXPECT_NE(what.find(part), std::string::npos) << what;
  };
  Config c = good;
  c.loss_chain[0].type_id = "ns3::NoSuchLossModel";
  expect_refused(c, {"ns3::NoSuchLossModel", "no such TypeId"});
  c = good;
  c.loss_chain.push_back({"ns3::ConstantSpeedPropagationDelayModel", {}});
  expect_refused(c, {"ns3::ConstantSpeedPropagationDelayModel", "not a ns3::PropagationLossModel"});
  c = good;
  c.loss_chain[0].attributes.push_back({"Exponentt", "3"});
  expect_refused(c, {"ns3::LogDistancePropagationLossModel", "Exponentt", "no such attribute"});
  for (const char* bad : {"3x", "3 ", "", "abc", "0x3"}) {
    c = good;
    c.loss_chain[0].attributes[0].value = bad;
    expect_refused(c, {"attribute Exponent = " + std::string(bad) + ":"});
  }
  c = good;
  c.standard = "80211z";
  expect_refused(c, {"80211z"});
  c = good;
  c.phy.push_back({"TxPowerStart", "high"});
  expect_refused(c, {"ns3::YansWifiPhy", "TxPowerStart", "high"});
  c = good;
  c.phy.push_back({"ChannelSettings", "{0, 20, BAND_7GHZ, 0}"});
  expect_refused(c, {"ChannelSettings", "BAND_7GHZ"});
  c = good;
  c.phy.push_back({"ChannelSettings", "{199, 20, BAND_5GHZ, 0}"});
  expect_refused(c, {"ChannelSettings", "no single channel"});
  c = good;
  c.phy.push_back({"Frequency", "5180"});  // read-only
  expect_refused(c, {"Frequency", "cannot be set"});
  c = good;
  c.preamble_detection.push_back({"Threshold", "4dB"});
  expect_refused(c, {"ns3::ThresholdPreambleDetectionModel", "Threshold"});
  c = good;
  c.rate_manager.type_id = "ns3::NoSuchManager";
  expect_refused(c, {"ns3::NoSuchManager"});
  c = good;
  c.rate_manager.attributes[0].value = "OfdmRate7Mbps";
  expect_refused(c, {"DataMode", "OfdmRate7Mbps", "no Wi-Fi mode"});
  c = good;
  c.standard = "80211b";  // OFDM modes with a DSSS PHY
  expect_refused(c, {"DataMode", "OfdmRate6Mbps", "802.11b"});
  c = good;
  c.rate_manager.attributes.push_back({"RtsCtsThreshold", "-5"});
  expect_refused(c, {"RtsCtsThreshold", "-5"});
  c = good;
  c.mac_queue = {{"MaxSize", "100"}};  // a QueueSize needs its unit
  expect_refused(c, {"ns3::WifiMacQueue", "MaxSize", "100"});
  c = good;
  c.mac_queue = {{"MaxSize", "64KB"}};
  expect_refused(c, {"MaxSize", "64KB", "packets"});
  c = good;
  c.mac_queue = {{"MaxDelay", "soon"}};
  expect_refused(c, {"MaxDelay", "soon"});
  c = good;
  c.txop = {{"MinCw", "many"}};
  expect_refused(c, {"ns3::Txop", "MinCw", "many"});
  c = good;
  c.routing_attributes = {{"HelloIntervall", "1s"}};
  expect_refused(c, {"ns3::aodv::RoutingProtocol", "HelloIntervall"});
  c = good;
  c.routing_attributes = {{"EnableHello", "maybe"}};
  expect_refused(c, {"EnableHello", "maybe"});
  c = good;
  c.routing_attributes = {{"HelloInterval", "0s"}};  // a timer of zero never lets time pass
  expect_refused(c, {"HelloInterval", "0s", "more than 0 s"});
  c = good;
  c.routing_attributes = {{"ActiveRouteTimeout", "1e7s"}};
  expect_refused(c, {"ActiveRouteTimeout", "1e7s", "longer"});
  c = good;
  c.routing_attributes = {{"TtlStart", "40"}};  // beyond NetDiameter 35: ns-3 would abort
  expect_refused(c, {"TtlStart 40 exceeds NetDiameter 35"});
  c = good;
  c.loss_chain[0].attributes.push_back({"ReferenceDistance", "-1"});
  expect_refused(c, {"ReferenceDistance", "more than 0"});
  c = good;
  c.loss_chain = {{"ns3::NakagamiPropagationLossModel", {{"m0", "0"}}}};
  expect_refused(c, {"ns3::NakagamiPropagationLossModel", "m0"});
  c = good;
  c.phy.push_back({"Slot", "0s"});
  expect_refused(c, {"Slot", "more than 0 s"});
  c = good;
  c.standard = "80211ac";
  c.rate_manager.attributes = {{"DataMode", "VhtMcs0"}, {"ControlMode", "VhtMcs0"}};
  c.phy.push_back({"Slot", "9us"});  // ns-3 aborts if an access beats PIFS on 80 MHz
  expect_refused(c, {"Slot", "80 MHz"});
  c = good;
  c.standard = "80211n";
  c.rate_manager = {"ns3::MinstrelWifiManager", {}};
  expect_refused(c, {"ns3::MinstrelWifiManager", "HT"});
  c = good;
  c.nodes = 0;
  expect_refused(c, {"nodes 0"});
  c = line_config(2, Routing::flooding);
  c.flooding.ttl = 0;
  expect_refused(c, {"flooding", "ttl 0"});
  // Nothing of a refused network is left behind.
  Ns3Network network(good);
  EXPECT_EQ(run(network, 1 * kS, line(2, 50.0), {message(1, 0, 1, 10 * kMs)}).size(), 1U);
}

TEST(FinitePowerGuard, TurnsPowersThatAreNoNumberIntoNoReception) {
  const auto guard = ns3::CreateObject<FinitePowerGuard>();
  const auto a = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  const auto b = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  EXPECT_EQ(guard->CalcRxPower(-71.5, a, b), -71.5);
  EXPECT_EQ(guard->CalcRxPower(std::nan(""), a, b), FinitePowerGuard::kNoPowerDbm);
  EXPECT_EQ(guard->CalcRxPower(std::numeric_limits<double>::infinity(), a, b),
            FinitePowerGuard::kNoPowerDbm);
  ns3::Simulator::Destroy();
}

TEST(Ns3Network, OneNetworkAtATime) {
  Ns3Network network(line_config(2, Routing::direct));
  EXPECT_NE(creation_error(line_config(2, Routing::direct)).find("another network"),
            std::string::npos);
}

TEST(Ns3Network, RefusesMalformedWindows) {
  Ns3Network network(line_config(2, Routing::direct));
  const std::vector<double> xy = line(2, 50.0);
  std::vector<Arrival> arrivals;
  const auto refused = [&](std::int64_t end_ns, const std::vector<double>& positions,
                           const std::vector<Message>& messages, const std::string& part) {
    try {
      network.run_window(end_ns, positions, messages, arrivals);
      ADD_FAILURE() << "accepted: " << part;
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
  };
  refused(0, xy, {}, "window end 0 ns");
  refused(10 * kMs, {0.0, 0.0}, {}, "2 coordinates for 2 nodes");
  refused(10 * kMs, {0.0, 0.0, 1.0 / 0.0, 0.0}, {}, "node 1's position");
  refused(10 * kMs, {-2e9, 0.0, 0.0, 0.0}, {}, "node 0's position");
  refused(10 * kMs, xy, {message(4, 0, 1, 10 * kMs)}, "message 4: inject_ns 10000000 outside");
  refused(10 * kMs, xy, {message(5, 2, 1, 1 * kMs)}, "message 5: source 2");
  refused(10 * kMs, xy, {message(6, 0, 9, 1 * kMs)}, "message 6: destination 9");
  // A refused window changes nothing: the network runs on from where it was.
  EXPECT_EQ(run(network, 10 * kMs, xy, {message(7, 0, 1, 0)}).size(), 1U);
  refused(10 * kMs, xy, {}, "window end 10000000 ns is not after the network's time 10000000 ns");
  EXPECT_TRUE(arrivals.empty());
}

}  // namespace
}  // namespace swarmnet::ns3engine
