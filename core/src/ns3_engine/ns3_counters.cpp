#include "ns3_engine/ns3_counters.hpp"

#include <ns3/aodv-packet.h>
#include <ns3/arp-cache.h>
#include <ns3/arp-header.h>
#include <ns3/arp-l3-protocol.h>
#include <ns3/ipv4-interface.h>
#include <ns3/llc-snap-header.h>
#include <ns3/qos-txop.h>
#include <ns3/traffic-control-layer.h>
#include <ns3/txop.h>
#include <ns3/udp-header.h>
#include <ns3/udp-l4-protocol.h>
#include <ns3/wifi-mac-header.h>
#include <ns3/wifi-mac-queue.h>
#include <ns3/wifi-phy-state-helper.h>
#include <ns3/wifi-phy.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "ns3_engine/message_tag.hpp"

namespace swarmnet::ns3engine {

namespace {

// The routing protocols' UDP ports (RFC 3561, RFC 3626; ns-3's DSDV).
constexpr std::uint16_t kAodvPort = 654;
constexpr std::uint16_t kOlsrPort = 698;
constexpr std::uint16_t kDsdvPort = 269;
// AODV broadcasts to its interface's subnet-directed address (the engine's /16).
const ns3::Ipv4Mask kSubnetMask("255.255.0.0");

template <typename PacketPtr>
bool is_data(const PacketPtr& packet) {
  MessageTag tag;
  return find_message(packet, tag);
}

// Connects `sink` to `object`'s trace source `name`. TraceConnect only returns false on a name
// it does not know (another ns-3 version): a count that silently stays 0 is worse than an error.
template <typename Object, typename Sink>
void connect_trace(const ns3::Ptr<Object>& object, const char* name, const Sink& sink) {
  if (!object->TraceConnectWithoutContext(name, sink)) {
    throw std::runtime_error(std::string("ns-3 engine: ") + object->GetInstanceTypeId().GetName() +
                             " has no trace source " + name);
  }
}

}  // namespace

CounterSinks::CounterSinks(Routing routing) : routing_(routing) {
  switch (routing) {
    case Routing::aodv:
      control_port_ = kAodvPort;
      break;
    case Routing::olsr:
      control_port_ = kOlsrPort;
      break;
    case Routing::dsdv:
      control_port_ = kDsdvPort;
      break;
    case Routing::direct:
    case Routing::flooding:
      break;
  }
}

void CounterSinks::connect(const ns3::Ptr<ns3::Node>& node, std::uint32_t node_id,
                           const ns3::Ptr<ns3::WifiNetDevice>& device) {
  const ns3::Ptr<ns3::WifiPhy> phy = device->GetPhy();
  connect_trace(phy, "PhyTxBegin", ns3::MakeCallback(&CounterSinks::on_phy_tx_begin, this));
  connect_trace(phy, "PhyRxDrop", ns3::MakeCallback(&CounterSinks::on_phy_rx_drop, this));
  connect_trace(phy->GetState(), "RxError", ns3::MakeCallback(&CounterSinks::on_rx_error, this));
  const ns3::Ptr<ns3::WifiMac> mac = device->GetMac();
  connect_trace(mac, "MacTx", ns3::MakeCallback(&CounterSinks::on_mac_tx, this));
  connect_trace(mac, "DroppedMpdu", ns3::MakeCallback(&CounterSinks::on_dropped_mpdu, this));
  std::vector<ns3::Ptr<ns3::WifiMacQueue>> queues;
  if (mac->GetQosSupported()) {
    for (const ns3::AcIndex ac : {ns3::AC_BE, ns3::AC_BK, ns3::AC_VI, ns3::AC_VO}) {
      queues.push_back(mac->GetQosTxop(ac)->GetWifiMacQueue());
    }
  } else {
    queues.push_back(mac->GetTxop()->GetWifiMacQueue());
  }
  for (const auto& queue : queues) {
    connect_trace(queue, "Enqueue", ns3::MakeCallback(&CounterSinks::on_queue_enqueue, this));
  }
  // The device stops its traffic-control queue while its MAC queue is full: a packet sent then is
  // dropped above the MAC, by the traffic-control layer.
  connect_trace(node->GetObject<ns3::TrafficControlLayer>(), "TcDrop",
                ns3::MakeCallback(&CounterSinks::on_tc_drop, this));

  const ns3::Ptr<ns3::Ipv4L3Protocol> ip = node->GetObject<ns3::Ipv4L3Protocol>();
  connect_trace(ip, "Tx", ns3::MakeCallback(&CounterSinks::on_ip_tx, this));
  connect_trace(ip, "Drop", ns3::MakeCallback(&CounterSinks::on_ip_drop, this));
  connect_trace(ip, "UnicastForward",
                ns3::MakeBoundCallback(&CounterSinks::on_unicast_forward, this, node_id));
  // Packets waiting for an address resolution are dropped by ArpL3Protocol (pending queue full,
  // neighbour known dead) and by the interface's ArpCache (resolution given up).
  connect_trace(node->GetObject<ns3::ArpL3Protocol>(), "Drop",
                ns3::MakeCallback(&CounterSinks::on_arp_queue_drop, this));
  for (std::uint32_t i = 0; i < ip->GetNInterfaces(); ++i) {
    if (const ns3::Ptr<ns3::ArpCache> cache = ip->GetInterface(i)->GetArpCache()) {
      connect_trace(cache, "Drop", ns3::MakeCallback(&CounterSinks::on_arp_give_up, this));
    }
  }
}

// The sinks take their arguments by value: ns-3 matches a sink to a trace source by its exact
// signature. NOLINTBEGIN(performance-unnecessary-value-param)
void CounterSinks::on_phy_tx_begin(ns3::Ptr<const ns3::Packet> packet, double /*power_w*/) {
  ++counts_.tx_frames;
  counts_.tx_bytes += packet->GetSize();
  ns3::WifiMacHeader header;
  if (packet->PeekHeader(header) == 0) return;
  if (header.IsData()) {
    ++counts_.data_frames;
    if (header.IsRetry()) ++counts_.retries;
  } else if (header.IsAck()) {
    ++counts_.ack_frames;
  } else if (header.IsRts()) {
    ++counts_.rts;
  } else if (header.IsCts()) {
    ++counts_.cts;
  }
}

void CounterSinks::on_rx_error(ns3::Ptr<const ns3::Packet> /*packet*/, double /*snr*/) {
  ++counts_.collisions;
}

void CounterSinks::on_phy_rx_drop(ns3::Ptr<const ns3::Packet> /*packet*/,
                                  ns3::WifiPhyRxfailureReason /*reason*/) {
  ++counts_.rx_drops;
}

// The MAC's MacTx sees each packet from above once, behind its LLC/SNAP header.
void CounterSinks::on_mac_tx(ns3::Ptr<const ns3::Packet> packet) {
  settle();
  if (is_data(packet)) {
    awaiting_enqueue_ = true;
    return;
  }
  ns3::LlcSnapHeader llc;
  if (packet->PeekHeader(llc) == 0 || llc.GetType() != ns3::ArpL3Protocol::PROT_NUMBER) return;
  const ns3::Ptr<ns3::Packet> copy = packet->Copy();
  copy->RemoveHeader(llc);
  ns3::ArpHeader arp;
  if (copy->RemoveHeader(arp) == 0) return;
  if (arp.IsRequest()) {
    ++counts_.arp_requests;
  } else if (arp.IsReply()) {
    ++counts_.arp_replies;
  }
}

void CounterSinks::on_queue_enqueue(ns3::Ptr<const ns3::WifiMpdu> /*mpdu*/) {
  awaiting_enqueue_ = false;
}

void CounterSinks::on_tc_drop(ns3::Ptr<const ns3::Packet> packet) {
  if (is_data(packet)) ++counts_.queue_full;
}

void CounterSinks::settle() {
  if (!awaiting_enqueue_) return;
  awaiting_enqueue_ = false;
  ++counts_.queue_full;
}

// Broadcast data counts too: a robot's broadcast lost in a full queue is lost all the same.
void CounterSinks::on_dropped_mpdu(ns3::WifiMacDropReason reason,
                                   ns3::Ptr<const ns3::WifiMpdu> mpdu) {
  if (!is_data(mpdu->GetPacket())) return;
  switch (reason) {
    case ns3::WIFI_MAC_DROP_FAILED_ENQUEUE:  // never fired by ns-3.37; counted by settle()
      break;
    case ns3::WIFI_MAC_DROP_EXPIRED_LIFETIME:  // waited longer than MaxDelay, as dcf80211 counts it
      ++counts_.buffer_timeout;
      break;
    case ns3::WIFI_MAC_DROP_REACHED_RETRY_LIMIT:
      ++counts_.retry_limit;
      break;
    case ns3::WIFI_MAC_DROP_QOS_OLD_PACKET:
      break;
  }
}

void CounterSinks::on_arp_queue_drop(ns3::Ptr<const ns3::Packet> packet) {
  ++counts_.arp_drops;
  if (is_data(packet)) ++counts_.arp_queue_full;  // or sent to a dead entry: one trace for both
}

// ARP asked its neighbour MaxRetries times in vain: the packets it held are dropped.
void CounterSinks::on_arp_give_up(ns3::Ptr<const ns3::Packet> packet) {
  ++counts_.arp_drops;
  if (is_data(packet)) ++counts_.arp_unresolved;
}

// Every IP packet sent on an interface, IP header first: the routing protocol's own.
void CounterSinks::on_ip_tx(ns3::Ptr<const ns3::Packet> packet, ns3::Ptr<ns3::Ipv4> /*ipv4*/,
                            std::uint32_t interface) {
  if (interface == 0 || control_port_ == 0) return;  // 0: loopback
  const ns3::Ptr<ns3::Packet> copy = packet->Copy();
  ns3::Ipv4Header ip;
  copy->RemoveHeader(ip);
  if (ip.GetProtocol() != ns3::UdpL4Protocol::PROT_NUMBER || ip.GetFragmentOffset() != 0) return;
  ns3::UdpHeader udp;
  copy->RemoveHeader(udp);
  if (udp.GetDestinationPort() != control_port_) return;
  ++counts_.control_packets;
  counts_.control_bytes += packet->GetSize();
  if (routing_ == Routing::aodv) count_aodv(ip, copy);
}

void CounterSinks::count_aodv(const ns3::Ipv4Header& ip, ns3::Ptr<ns3::Packet> udp_payload) {
  ns3::aodv::TypeHeader type;
  udp_payload->RemoveHeader(type);
  if (!type.IsValid()) return;
  switch (type.Get()) {
    case ns3::aodv::AODVTYPE_RREQ:
      ++counts_.rreq;
      break;
    case ns3::aodv::AODVTYPE_RREP: {
      // ns-3's AODV sends HELLO as an RREP for itself, hop count 0, broadcast.
      ns3::aodv::RrepHeader rrep;
      udp_payload->RemoveHeader(rrep);
      const ns3::Ipv4Address to = ip.GetDestination();
      const bool broadcast = to.IsBroadcast() || to.IsSubnetDirectedBroadcast(kSubnetMask);
      const bool hello = broadcast && rrep.GetDst() == ip.GetSource() && rrep.GetHopCount() == 0;
      ++(hello ? counts_.hello : counts_.rrep);
      break;
    }
    case ns3::aodv::AODVTYPE_RERR:
      ++counts_.rerr;
      break;
    case ns3::aodv::AODVTYPE_RREP_ACK:
      ++counts_.rrep_ack;
      break;
  }
}

void CounterSinks::on_ip_drop(const ns3::Ipv4Header& /*header*/,
                              ns3::Ptr<const ns3::Packet> payload,
                              ns3::Ipv4L3Protocol::DropReason reason, ns3::Ptr<ns3::Ipv4> /*ipv4*/,
                              std::uint32_t /*interface*/) {
  if (!is_data(payload)) return;
  switch (reason) {
    case ns3::Ipv4L3Protocol::DROP_NO_ROUTE:
      ++counts_.no_route;
      break;
    case ns3::Ipv4L3Protocol::DROP_TTL_EXPIRED:
      ++counts_.ttl_expired;
      break;
    case ns3::Ipv4L3Protocol::DROP_ROUTE_ERROR:  // AODV's request queue gave up on it
      ++counts_.buffer_timeout;
      break;
    default:
      break;
  }
}

// ns-3's AODV parks a packet without a route on the loopback interface and, once it has one,
// "forwards" it from its own source: that is no forward, and not counted.
void CounterSinks::on_unicast_forward(CounterSinks* sinks, std::uint32_t node_id,
                                      const ns3::Ipv4Header& /*header*/,
                                      ns3::Ptr<const ns3::Packet> payload,
                                      std::uint32_t /*interface*/) {
  MessageTag tag;
  if (find_message(payload, tag) && tag.source() != node_id) ++sinks->counts_.data_forwards;
}

// NOLINTEND(performance-unnecessary-value-param)

Report CounterSinks::report(std::uint64_t events) const {
  const Counts& c = counts_;
  Report report;
  report.events = events;
  report.mac = {{"tx_frames", c.tx_frames},
                {"tx_bytes", c.tx_bytes},
                {"data_frames", c.data_frames},
                {"ack_frames", c.ack_frames},
                {"rts", c.rts},
                {"cts", c.cts},
                {"retries", c.retries},
                {"collisions", c.collisions},
                {"rx_drops", c.rx_drops},
                {"arp_requests", c.arp_requests},
                {"arp_replies", c.arp_replies},
                {"arp_drops", c.arp_drops}};
  report.routing = {{"control_packets", c.control_packets},
                    {"control_bytes", c.control_bytes},
                    {"data_forwards", c.data_forwards}};
  if (routing_ == Routing::aodv) {
    report.routing.insert(report.routing.end(), {{"rreq", c.rreq},
                                                 {"rrep", c.rrep},
                                                 {"hello", c.hello},
                                                 {"rerr", c.rerr},
                                                 {"rrep_ack", c.rrep_ack}});
  } else if (routing_ == Routing::flooding) {
    report.routing.insert(report.routing.end(),
                          {{"duplicates", c.duplicates}, {"ttl_expired", c.flooding_ttl_expired}});
  }
  report.drops = {{"no_route", c.no_route},
                  {"queue_full", c.queue_full},
                  {"ttl_expired", c.ttl_expired},
                  {"retry_limit", c.retry_limit},
                  {"buffer_timeout", c.buffer_timeout},
                  {"arp_queue_full", c.arp_queue_full},
                  {"arp_unresolved", c.arp_unresolved}};
  return report;
}

}  // namespace swarmnet::ns3engine
