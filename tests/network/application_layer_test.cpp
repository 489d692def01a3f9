#include "network/application_layer.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "network_test_support.hpp"
#include "outputs/run_summary.hpp"

namespace swarmnet {
namespace {

TEST(NetworkApplication, MessageToItselfIsDeliveredAtOnce) {
  PluginLoader loader;
  const NetworkSettings settings = test::make_settings(loader, 3);
  const auto out = test::run(
      settings, loader,
      test::fixed_batches(settings, test::line_positions(3, 50.0), 1, {test::message(4, 2, 2)}));
  ASSERT_EQ(out.deliveries.size(), 1U);
  EXPECT_EQ(out.deliveries[0].receiver, 2U);
  EXPECT_EQ(out.deliveries[0].hops, 0U);
  EXPECT_EQ(out.deliveries[0].delivered_at, out.deliveries[0].sent_at);
  EXPECT_EQ(out.report["mac"]["tx_frames"], 0);
  EXPECT_EQ(out.report["pdr"].get<double>(), 1.0);
  const auto trace = test::parse_trace(out.trace);
  ASSERT_EQ(trace.size(), 2U);
  EXPECT_EQ(trace[0].event, "send");
  EXPECT_EQ(trace[1].event, "deliver");
}

class NullRouting final : public Routing {
 public:
  void attach(RoutingContext& /*context*/) override {}
  void send(Packet packet) override { sent.push_back(std::move(packet)); }
  void receive(Packet /*packet*/, NodeId /*from*/) override {}
  std::vector<Packet> sent;
};

class NetworkApplicationUnit : public ::testing::Test {
 protected:
  NetworkMetrics metrics_;
  std::ostringstream trace_text_;
  PacketTraceWriter trace_{&trace_text_};
  PacketUidSource uids_;
  SendReports reports_;
  ApplicationLayer application_{3, metrics_, trace_, uids_, reports_};
  NullRouting routing_;
  std::vector<Delivery> deliveries_;
};

TEST_F(NetworkApplicationUnit, InjectionBuildsThePacket) {
  const auto payload = std::make_shared<const Payload>(Payload(10, std::byte{7}));
  application_.inject({12, 0, 2, 9, payload}, SimTime{500}, routing_);
  application_.inject({13, 1, kBroadcast, 0, payload}, SimTime{600}, routing_);
  ASSERT_EQ(routing_.sent.size(), 2U);
  const Packet& p = routing_.sent[0];
  EXPECT_EQ(p.uid, 1U);
  EXPECT_EQ(routing_.sent[1].uid, 2U);
  EXPECT_EQ(p.message_id, 12U);
  EXPECT_EQ(p.source, 0U);
  EXPECT_EQ(p.destination, 2U);
  EXPECT_EQ(p.sent_at, SimTime{500});
  EXPECT_EQ(p.hops, 0U);
  EXPECT_EQ(p.port, 9U);          // the controller port, carried beside the bytes
  EXPECT_EQ(p.payload, payload);  // shared, not copied
  EXPECT_EQ(metrics_.sent(), 2U);
  EXPECT_EQ(metrics_.unicast_sent(), 1U);
  EXPECT_EQ(application_.undelivered_unicast(), 1U);
  trace_.finish();
  EXPECT_EQ(trace_text_.str(), std::string(PacketTraceWriter::kHeader) +
                                   "500,send,0,1,12,0,2,0,38,\n"
                                   "600,send,1,2,13,1,-1,0,38,\n");
}

TEST_F(NetworkApplicationUnit, DuplicatesAreSuppressedPerNode) {
  application_.set_output(&deliveries_);
  application_.inject({1, 0, kBroadcast, 0, nullptr}, SimTime{0}, routing_);
  Packet copy = routing_.sent.at(0);
  copy.hops = 2;
  EXPECT_TRUE(application_.deliver(1, copy, SimTime{100}));
  EXPECT_FALSE(application_.deliver(1, copy, SimTime{200}));  // same node again
  EXPECT_TRUE(application_.deliver(2, copy, SimTime{300}));   // another node
  ASSERT_EQ(deliveries_.size(), 2U);
  EXPECT_EQ(deliveries_[0].receiver, 1U);
  EXPECT_EQ(deliveries_[0].hops, 2U);
  EXPECT_EQ(deliveries_[0].delivered_at, SimTime{100});
  EXPECT_EQ(deliveries_[1].receiver, 2U);
  const auto report = network_report_json(metrics_.report(application_.undelivered_unicast(), 0));
  EXPECT_EQ(report["packets"]["broadcast_deliveries"], 2);
  EXPECT_EQ(report["packets"]["duplicates"], 1);
}

TEST_F(NetworkApplicationUnit, OnlyTheDestinationsFirstDeliveryCounts) {
  application_.set_output(&deliveries_);
  application_.inject({5, 0, 2, 6, nullptr}, SimTime{1'000}, routing_);
  Packet copy = routing_.sent.at(0);
  copy.hops = 3;
  EXPECT_TRUE(application_.deliver(2, copy, SimTime{5'000}));
  EXPECT_FALSE(application_.deliver(2, copy, SimTime{6'000}));
  ASSERT_EQ(deliveries_.size(), 1U);
  EXPECT_EQ(deliveries_[0].port, 6U);  // delivered to the port it was sent to
  EXPECT_EQ(application_.undelivered_unicast(), 0U);
  const auto report = network_report_json(metrics_.report(application_.undelivered_unicast(), 0));
  EXPECT_EQ(report["packets"]["delivered"], 1);
  EXPECT_EQ(report["pdr"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(report["delay_s"]["mean"].get<double>(), 4e-6);
  EXPECT_DOUBLE_EQ(report["hops_mean"].get<double>(), 3.0);
}

TEST_F(NetworkApplicationUnit, TheDuplicateMemoryIsBoundedByItsWindow) {
  application_.set_output(&deliveries_);
  application_.inject({1, 0, kBroadcast, 0, nullptr}, SimTime{0}, routing_);
  const Packet copy = routing_.sent.at(0);
  EXPECT_TRUE(application_.deliver(1, copy, SimTime{10}));
  // Past the window the entry is forgotten, and a straggling copy counts as new.
  EXPECT_TRUE(application_.deliver(1, copy, ApplicationLayer::kDuplicateWindow + SimTime{1}));
  EXPECT_EQ(deliveries_.size(), 2U);
}

TEST(NetworkMetrics, PercentilesUseTheNearestRank) {
  NetworkMetrics metrics;
  for (int i = 1; i <= 20; ++i) {
    metrics.message_sent(false);
    metrics.unicast_delivered(SimTime{i * 1'000'000}, static_cast<std::uint32_t>(i % 3));
  }
  metrics.message_sent(false);  // never delivered
  const auto report = network_report_json(metrics.report(1, 0));
  EXPECT_DOUBLE_EQ(report["pdr"].get<double>(), 20.0 / 21.0);
  EXPECT_DOUBLE_EQ(report["delay_s"]["mean"].get<double>(), 0.0105);
  EXPECT_DOUBLE_EQ(report["delay_s"]["p50"].get<double>(), 0.010);  // rank ceil(0.5 * 20) = 10
  EXPECT_DOUBLE_EQ(report["delay_s"]["p95"].get<double>(), 0.019);  // rank ceil(0.95 * 20) = 19
  metrics.mac_count("retries", 4);
  metrics.mac_count("backoffs", 2);
  metrics.routing_count("control_rreq", 1);
  const auto later = network_report_json(metrics.report(1, 0));
  EXPECT_EQ(later["mac"]["retries"], 4);
  EXPECT_EQ(later["mac"]["backoffs"], 2);
  EXPECT_EQ(later["routing"]["control_rreq"], 1);
}

}  // namespace
}  // namespace swarmnet
