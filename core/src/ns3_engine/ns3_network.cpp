#include "ns3_engine/ns3_network.hpp"

#include <ns3/aodv-helper.h>
#include <ns3/config.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/dsdv-helper.h>
#include <ns3/dsdv-routing-protocol.h>
#include <ns3/internet-stack-helper.h>
#include <ns3/ipv4-address-generator.h>
#include <ns3/ipv4-address-helper.h>
#include <ns3/ipv4-interface-container.h>
#include <ns3/ipv4-static-routing-helper.h>
#include <ns3/mac48-address.h>
#include <ns3/neighbor-cache-helper.h>
#include <ns3/olsr-helper.h>
#include <ns3/propagation-delay-model.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/qos-txop.h>
#include <ns3/rng-seed-manager.h>
#include <ns3/simulator.h>
#include <ns3/traffic-control-helper.h>
#include <ns3/txop.h>
#include <ns3/wifi-mac-queue.h>
#include <ns3/wifi-mac.h>
#include <ns3/wifi-net-device.h>
#include <ns3/yans-wifi-channel.h>
#include <ns3/yans-wifi-helper.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

#include "ns3_engine/attribute_check.hpp"
#include "ns3_engine/finite_power_guard.hpp"
#include "ns3_engine/network_plan.hpp"

namespace swarmnet::ns3engine {

namespace {

// ns-3's simulator, node list and configuration are process-wide: one network at a time.
std::atomic<bool> g_network_exists{false};

constexpr std::uint16_t kMessagePort = 9;
constexpr double kMaxCoordinateM = 1e9;

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("ns-3 engine: " + what);
}

// First stream numbers of each model's random variables, fixed and far apart, so that the
// streams of one do not move when another uses more (another standard, more nodes).
constexpr std::int64_t kWifiStreams = 0;
constexpr std::int64_t kChannelStreams = std::int64_t{1} << 24;
constexpr std::int64_t kInternetStreams = std::int64_t{2} << 24;
constexpr std::int64_t kRoutingStreams = std::int64_t{3} << 24;
constexpr std::int64_t kFloodingStreams = std::int64_t{4} << 24;

// ns-3's helpers keep their factories protected; the engine's come checked, whole.
class EngineWifiHelper final : public ns3::WifiHelper {
 public:
  void set_rate_manager(const ns3::ObjectFactory& factory) { m_stationManager = factory; }
};

class EnginePhyHelper final : public ns3::YansWifiPhyHelper {
 public:
  void set_preamble_detection(const ns3::ObjectFactory& factory) {
    for (ns3::ObjectFactory& each : m_preambleDetectionModel) each = factory;
  }
  void set_error_rate_model(const ns3::ObjectFactory& factory) {
    for (ns3::ObjectFactory& each : m_errorRateModel) each = factory;
  }
};

template <typename Helper>
void set_on_helper(Helper& helper, const std::vector<CheckedAttribute>& attributes) {
  for (const CheckedAttribute& attribute : attributes) helper.Set(attribute.name, *attribute.value);
}

void set_on_object(const ns3::Ptr<ns3::Object>& object,
                   const std::vector<CheckedAttribute>& attributes) {
  for (const CheckedAttribute& attribute : attributes) {
    object->SetAttribute(attribute.name, *attribute.value);
  }
}

ns3::Ptr<ns3::YansWifiChannel> make_channel(const Plan& plan) {
  const auto channel = ns3::CreateObject<ns3::YansWifiChannel>();
  channel->SetPropagationDelayModel(ns3::CreateObject<ns3::ConstantSpeedPropagationDelayModel>());
  ns3::Ptr<ns3::PropagationLossModel> first;
  ns3::Ptr<ns3::PropagationLossModel> last;
  for (const ns3::ObjectFactory& factory : plan.loss_chain) {
    const auto model = factory.Create<ns3::PropagationLossModel>();
    if (last) {
      last->SetNext(model);
    } else {
      first = model;
    }
    last = model;
  }
  last->SetNext(ns3::CreateObject<FinitePowerGuard>());
  channel->SetPropagationLossModel(first);
  return channel;
}

// Txop and queue settings go on the live MAC objects: the helper has no factory for them. With
// QoS, robot messages, ARP and routing control all go best effort (no socket priority), so the
// Txop settings are AC_BE's; every queue gets the queue settings.
void configure_mac(const ns3::Ptr<ns3::WifiMac>& mac, const Plan& plan) {
  std::vector<ns3::Ptr<ns3::WifiMacQueue>> queues;
  if (plan.qos) {
    set_on_object(mac->GetQosTxop(ns3::AC_BE), plan.txop);
    for (const ns3::AcIndex ac : {ns3::AC_BE, ns3::AC_BK, ns3::AC_VI, ns3::AC_VO}) {
      queues.push_back(mac->GetQosTxop(ac)->GetWifiMacQueue());
    }
  } else {
    set_on_object(mac->GetTxop(), plan.txop);
    queues.push_back(mac->GetTxop()->GetWifiMacQueue());
  }
  for (const auto& queue : queues) set_on_object(queue, plan.mac_queue);
}

std::int64_t assign_dsdv_streams(const ns3::NodeContainer& nodes, std::int64_t stream) {
  const std::int64_t first = stream;
  for (std::uint32_t i = 0; i < nodes.GetN(); ++i) {
    const auto routing = nodes.Get(i)->GetObject<ns3::Ipv4>()->GetRoutingProtocol();
    if (const auto dsdv = ns3::DynamicCast<ns3::dsdv::RoutingProtocol>(routing)) {
      stream += dsdv->AssignStreams(stream);
    }
  }
  return stream - first;
}

}  // namespace

Ns3Network::Ns3Network(const Config& config) : counters_(config.routing) {
  if (g_network_exists.exchange(true)) {
    fail("another network exists (ns-3's simulator is one per process): delete it first");
  }
  try {
    build(config);
  } catch (...) {
    ns3::Simulator::Destroy();
    g_network_exists = false;
    throw;
  }
}

Ns3Network::~Ns3Network() {
  ns3::Simulator::Destroy();
  g_network_exists = false;
}

void Ns3Network::build(const Config& config) {
  // Nothing of a previous network in this process may leak in: attribute defaults, the address
  // registries (a second 10.1.0.1 would be fatal), the MAC address counter.
  ns3::Config::Reset();
  ns3::Ipv4AddressGenerator::Reset();
  ns3::Mac48Address::ResetAllocationIndex();
  const Plan plan = make_plan(config);
  ns3::RngSeedManager::SetSeed(1);
  ns3::RngSeedManager::SetRun(config.run);

  node_count_ = config.nodes;
  nodes_.Create(node_count_);
  for (std::uint32_t i = 0; i < node_count_; ++i) {
    const auto mobility = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
    nodes_.Get(i)->AggregateObject(mobility);
    mobility_.emplace_back(mobility);
  }

  const ns3::Ptr<ns3::YansWifiChannel> channel = make_channel(plan);
  EnginePhyHelper phy;
  phy.SetChannel(channel);
  set_on_helper(phy, plan.phy);
  phy.set_preamble_detection(plan.preamble_detection);
  if (plan.error_rate_model) phy.set_error_rate_model(*plan.error_rate_model);
  EngineWifiHelper wifi;
  wifi.SetStandard(plan.standard);
  wifi.set_rate_manager(plan.rate_manager);
  ns3::WifiMacHelper mac;
  mac.SetType("ns3::AdhocWifiMac");
  const ns3::NetDeviceContainer devices = wifi.Install(phy, mac, nodes_);
  for (std::uint32_t i = 0; i < node_count_; ++i) {
    const auto device = ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(i));
    set_on_object(device->GetPhy(), plan.phy_after_install);
    configure_mac(device->GetMac(), plan);
  }

  // IPv4 with ns-3's ARP; no IPv6, which the engine never addresses.
  ns3::InternetStackHelper internet;
  internet.SetIpv6StackInstall(false);
  ns3::AodvHelper aodv;
  ns3::OlsrHelper olsr;
  ns3::DsdvHelper dsdv;
  switch (config.routing) {
    case Routing::aodv:
      set_on_helper(aodv, plan.routing);
      internet.SetRoutingHelper(aodv);
      break;
    case Routing::olsr:
      set_on_helper(olsr, plan.routing);
      internet.SetRoutingHelper(olsr);
      break;
    case Routing::dsdv:
      set_on_helper(dsdv, plan.routing);
      internet.SetRoutingHelper(dsdv);
      break;
    case Routing::direct:
    case Routing::flooding:
      // One subnet: the static routing's interface route reaches every node in one hop.
      internet.SetRoutingHelper(ns3::Ipv4StaticRoutingHelper());
      break;
  }
  internet.Install(nodes_);
  ns3::Ipv4AddressHelper addresses;
  addresses.SetBase("10.1.0.0", "255.255.0.0");
  const ns3::Ipv4InterfaceContainer interfaces = addresses.Assign(devices);
  // Assign gives each device ns-3's default queue disc (fq_codel) above the MAC, with flow
  // control: the MAC queue would then never fill, and CoDel would drop uncounted. As in SwarmNet,
  // the MAC queue is the only queue.
  ns3::TrafficControlHelper().Uninstall(devices);
  // The IPv4 interfaces' form: the channel-wide one looks for IPv6 too, which is not installed.
  if (config.static_arp) ns3::NeighborCacheHelper().PopulateNeighborCache(interfaces);

  wifi.AssignStreams(devices, kWifiStreams);
  channel->AssignStreams(kChannelStreams);
  internet.AssignStreams(nodes_, kInternetStreams);
  switch (config.routing) {
    case Routing::aodv:
      aodv.AssignStreams(nodes_, kRoutingStreams);
      break;
    case Routing::olsr:
      olsr.AssignStreams(nodes_, kRoutingStreams);
      break;
    case Routing::dsdv:
      assign_dsdv_streams(nodes_, kRoutingStreams);
      break;
    case Routing::direct:
    case Routing::flooding:
      break;
  }

  world_.port = kMessagePort;
  world_.counts = &counters_.counts();
  for (std::uint32_t i = 0; i < node_count_; ++i) {
    world_.addresses.push_back(interfaces.GetAddress(i));
    counters_.connect(nodes_.Get(i), i, ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(i)));
  }
  for (std::uint32_t i = 0; i < node_count_; ++i) {
    if (config.routing == Routing::flooding) {
      auto jitter = ns3::CreateObject<ns3::UniformRandomVariable>();
      jitter->SetStream(kFloodingStreams + i);
      endpoints_.push_back(
          std::make_unique<FloodingEndpoint>(nodes_.Get(i), i, world_, config.flooding, jitter));
    } else {
      endpoints_.push_back(std::make_unique<DatagramEndpoint>(nodes_.Get(i), i, world_));
    }
  }
}

void Ns3Network::check_window(std::int64_t end_ns, const std::vector<double>& xy,
                              const std::vector<Message>& messages) const {
  if (end_ns <= now_ns_) {
    fail("window end " + std::to_string(end_ns) + " ns is not after the network's time " +
         std::to_string(now_ns_) + " ns");
  }
  if (xy.size() != 2 * static_cast<std::size_t>(node_count_)) {
    fail("window to " + std::to_string(end_ns) + " ns: " + std::to_string(xy.size()) +
         " coordinates for " + std::to_string(node_count_) + " nodes (2 per node)");
  }
  for (std::size_t i = 0; i < xy.size(); ++i) {
    // Beyond a million kilometres the propagation delay would overflow ns-3's time.
    if (!std::isfinite(xy[i]) || std::abs(xy[i]) > kMaxCoordinateM) {
      fail("window to " + std::to_string(end_ns) + " ns: node " + std::to_string(i / 2) +
           "'s position is not a finite coordinate within 1e9 m");
    }
  }
  for (const Message& message : messages) {
    const std::string which = "message " + std::to_string(message.message_id) + ": ";
    if (message.inject_ns < now_ns_ || message.inject_ns >= end_ns) {
      fail(which + "inject_ns " + std::to_string(message.inject_ns) + " outside the window [" +
           std::to_string(now_ns_) + ", " + std::to_string(end_ns) + ")");
    }
    if (message.source >= node_count_) {
      fail(which + "source " + std::to_string(message.source) + " is not a node");
    }
    if (message.destination != kBroadcastNode && message.destination >= node_count_) {
      fail(which + "destination " + std::to_string(message.destination) + " is not a node");
    }
  }
}

void Ns3Network::run_window(std::int64_t end_ns, const std::vector<double>& xy,
                            const std::vector<Message>& messages, std::vector<Arrival>& arrivals) {
  check_window(end_ns, xy, messages);
  for (std::uint32_t i = 0; i < node_count_; ++i) {
    const std::size_t x = 2 * static_cast<std::size_t>(i);
    mobility_[i]->SetPosition(ns3::Vector(xy[x], xy[x + 1], 0.0));
  }
  const ns3::Time now = ns3::Simulator::Now();
  for (const Message& message : messages) {
    Endpoint* endpoint = endpoints_[message.source].get();
    ns3::Simulator::ScheduleWithContext(nodes_.Get(message.source)->GetId(),
                                        ns3::NanoSeconds(message.inject_ns) - now,
                                        [endpoint, message]() { endpoint->send(message); });
  }
  world_.arrivals = &arrivals;
  try {
    run_until(end_ns);
    counters_.settle();
  } catch (...) {
    world_.arrivals = nullptr;
    throw;
  }
  world_.arrivals = nullptr;
  now_ns_ = end_ns;
}

// ns-3 runs the events of one time in the order they were scheduled, and Stop(delay) is one of
// them: a stop at end_ns would let through the events at end_ns scheduled before it (timers
// from earlier windows) and hold back those scheduled after. So the run stops at end_ns - 1,
// then drains that last nanosecond with Stop(0) passes: each runs the events already there, and
// the drain ends with a pass that ran nothing but its own stop. Every event before end_ns has
// then run and none at or after it; the clock rests at end_ns - 1, where nothing is left.
void Ns3Network::run_until(std::int64_t end_ns) {
  ns3::Simulator::Stop(ns3::NanoSeconds(end_ns - 1) - ns3::Simulator::Now());
  ++stop_events_;
  ns3::Simulator::Run();
  for (;;) {
    const std::uint64_t before = ns3::Simulator::GetEventCount();
    ns3::Simulator::Stop(ns3::Seconds(0));
    ++stop_events_;
    ns3::Simulator::Run();
    if (ns3::Simulator::GetEventCount() - before == 1) break;
  }
}

Report Ns3Network::report() const {
  return counters_.report(ns3::Simulator::GetEventCount() - stop_events_);
}

}  // namespace swarmnet::ns3engine
