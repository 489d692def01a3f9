// The scenario's network settings as the ns-3 engine receives them (ns3_host/ns3_settings.hpp):
// each key and plugin parameter becomes the ns-3 attribute ns3_counterparts.hpp names, with its
// unit converted, and what the scenario check would refuse is refused here too.
#include "ns3_host/ns3_settings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "ns3_study_settings.hpp"

namespace swarmnet {
namespace {

using test::aodv_params;

PluginChoice choice(std::string name, PluginKind kind, ParamSet params) {
  return test::plugin(std::move(name), kind, std::move(params));
}

NetworkSettings paper_settings() {
  return test::study_settings(12, 7, choice("aodv", PluginKind::routing, aodv_params()));
}

std::string value_of(const std::vector<ns3engine::Attribute>& attributes, const std::string& name) {
  const auto it = std::find_if(attributes.begin(), attributes.end(),
                               [&](const auto& a) { return a.name == name; });
  return it == attributes.end() ? "(absent)" : it->value;
}

TEST(Ns3Settings, ThePaperScenarioMapsOntoNs3sAttributes) {
  const ns3engine::Config config = ns3_config_for(paper_settings());
  EXPECT_EQ(config.nodes, 12U);
  EXPECT_EQ(config.run, 7U);
  EXPECT_EQ(config.standard, "80211a");
  ASSERT_EQ(config.loss_chain.size(), 1U);
  EXPECT_EQ(config.loss_chain[0].type_id, "ns3::LogDistancePropagationLossModel");
  EXPECT_EQ(value_of(config.loss_chain[0].attributes, "Exponent"), "3");
  EXPECT_EQ(value_of(config.loss_chain[0].attributes, "ReferenceLoss"), "46.677700000000002");
  EXPECT_EQ(value_of(config.phy, "TxPowerStart"), "27.053100000000001");
  EXPECT_EQ(value_of(config.phy, "CcaEdThreshold"), "-62");
  EXPECT_EQ(value_of(config.phy, "CcaSensitivity"), "-82");
  EXPECT_EQ(value_of(config.phy, "Slot"), "9000ns");
  EXPECT_EQ(value_of(config.preamble_detection, "MinimumRssi"), "-82");
  EXPECT_EQ(config.error_rate_model.type_id, "ns3::NistErrorRateModel");
  EXPECT_EQ(config.rate_manager.type_id, "ns3::ConstantRateWifiManager");
  EXPECT_EQ(value_of(config.rate_manager.attributes, "DataMode"), "OfdmRate6Mbps");
  EXPECT_EQ(value_of(config.rate_manager.attributes, "MaxSsrc"), "7");
  EXPECT_EQ(value_of(config.txop, "MinCw"), "15");
  EXPECT_EQ(value_of(config.mac_queue, "MaxSize"), "500p");
  EXPECT_EQ(value_of(config.mac_queue, "MaxDelay"), "500000000ns");
  EXPECT_EQ(config.routing, ns3engine::Routing::aodv);
  EXPECT_EQ(value_of(config.routing_attributes, "HelloInterval"), "1000000000ns");
  EXPECT_EQ(value_of(config.routing_attributes, "GratuitousReply"), "true");
  EXPECT_EQ(config.arp, ns3engine::Arp::dynamic);
}

TEST(Ns3Settings, AodvTimesGivenAsZeroAreDerivedAsThePluginDerivesThem) {
  const ns3engine::Config config = ns3_config_for(paper_settings());
  // RFC 3561 with the defaults: these are also ns-3.37's own defaults.
  EXPECT_EQ(value_of(config.routing_attributes, "NetTraversalTime"), "2800000000ns");
  EXPECT_EQ(value_of(config.routing_attributes, "PathDiscoveryTime"), "5600000000ns");
  EXPECT_EQ(value_of(config.routing_attributes, "NextHopWait"), "50000000ns");
  EXPECT_EQ(value_of(config.routing_attributes, "MyRouteTimeout"), "11200000000ns");
  EXPECT_EQ(value_of(config.routing_attributes, "BlackListTimeout"), "5600000000ns");
  EXPECT_EQ(value_of(config.routing_attributes, "DeletePeriod"), "15000000000ns");
  // Given, a time is kept, and what derives from it follows.
  NetworkSettings s = paper_settings();
  s.network.routing.params.set("net_traversal_time_s", 1.0);
  const ns3engine::Config given = ns3_config_for(s);
  EXPECT_EQ(value_of(given.routing_attributes, "NetTraversalTime"), "1000000000ns");
  EXPECT_EQ(value_of(given.routing_attributes, "PathDiscoveryTime"), "2000000000ns");
}

TEST(Ns3Settings, OtherStandardsKeepTheirOwnTimingAndNameTheirModes) {
  NetworkSettings s = paper_settings();
  s.network.ns3.standard = "80211g";
  s.network.mac.params.set("data_rate_bps", 24e6);
  const ns3engine::Config g = ns3_config_for(s);
  EXPECT_EQ(value_of(g.rate_manager.attributes, "DataMode"), "ErpOfdmRate24Mbps");
  EXPECT_EQ(value_of(g.phy, "Slot"), "(absent)");
  EXPECT_TRUE(g.txop.empty());
  s.network.ns3.standard = "80211n";
  EXPECT_THROW((void)ns3_config_for(s), std::invalid_argument) << "no mode named for 802.11n";
  s.network.ns3.data_mode = "HtMcs7";
  s.network.ns3.control_mode = "OfdmRate6Mbps";
  EXPECT_EQ(value_of(ns3_config_for(s).rate_manager.attributes, "DataMode"), "HtMcs7");
}

TEST(Ns3Settings, IpRoutingFloodingAndArp) {
  NetworkSettings s = paper_settings();
  s.network.routing = choice("direct", PluginKind::routing, ParamSet());
  s.network.ns3.ip_routing = "olsr";
  s.network.arp.reset();
  const ns3engine::Config olsr = ns3_config_for(s);
  EXPECT_EQ(olsr.routing, ns3engine::Routing::olsr);
  EXPECT_EQ(value_of(olsr.routing_attributes, "HelloInterval"), "2000000000ns");
  EXPECT_EQ(olsr.arp, ns3engine::Arp::static_no_feedback);
  s.network.routing = choice(
      "flooding", PluginKind::routing,
      ParamSet(
          {{"ttl", std::int64_t{5}}, {"jitter_max_s", 0.002}, {"cache_size", std::int64_t{99}}}));
  EXPECT_THROW((void)ns3_config_for(s), std::invalid_argument) << "olsr under flooding";
  s.network.ns3.ip_routing = "none";
  const ns3engine::Config flooding = ns3_config_for(s);
  EXPECT_EQ(flooding.routing, ns3engine::Routing::flooding);
  EXPECT_EQ(flooding.flooding.ttl, 5U);
  EXPECT_EQ(flooding.flooding.cache_size, 99U);
}

TEST(Ns3Settings, AodvsLayerTwoFeedbackFollowsTheArpEntries) {
  NetworkSettings s = paper_settings();
  s.network.arp.reset();
  EXPECT_EQ(ns3_config_for(s).arp, ns3engine::Arp::static_with_feedback);
  s.network.routing.params.set("link_layer_feedback", false);
  EXPECT_EQ(ns3_config_for(s).arp, ns3engine::Arp::static_no_feedback);
  s.network.arp = ArpTimings{};
  EXPECT_THROW((void)ns3_config_for(s), std::invalid_argument) << "ARP always gives feedback";
}

TEST(Ns3Settings, WhatHasNoCounterpartIsRefused) {
  NetworkSettings s = paper_settings();
  s.network.mac = choice("ideal_mac", PluginKind::mac, ParamSet());
  EXPECT_THROW((void)ns3_config_for(s), std::invalid_argument);
  s = paper_settings();
  s.network.propagation = {choice("disk", PluginKind::propagation, ParamSet())};
  EXPECT_THROW((void)ns3_config_for(s), std::invalid_argument);
  s = paper_settings();
  s.network.phy.model = PhyModel::threshold;
  EXPECT_THROW((void)ns3_config_for(s), std::invalid_argument);
}

}  // namespace
}  // namespace swarmnet
