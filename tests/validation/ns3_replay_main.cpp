// swarmnet_ns3_replay: replays a SwarmNet run's mobility trace and traffic schedule in ns-3.37
// (YansWifi 802.11a ad hoc at a constant 6 Mbps, log-distance propagation, UDP over IPv4, one
// node per robot) with routing `direct`, `flooding` or `aodv`, and writes the same measures as
// SwarmNet's summary.json as JSON, with ARP's figures. By default the IP stack is ns-3's as users
// run it (ARP, AODV with layer-2 feedback); --aligned fills the ARP caches in advance instead.
// docs/validation.md explains the setup.
#include <ns3/aodv-helper.h>
#include <ns3/aodv-packet.h>
#include <ns3/core-module.h>
#include <ns3/internet-module.h>
#include <ns3/mobility-module.h>
#include <ns3/network-module.h>
#include <ns3/ns2-mobility-helper.h>
#include <ns3/traffic-control-helper.h>
#include <ns3/traffic-control-layer.h>
#include <ns3/wifi-module.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "datagram_endpoint.hpp"
#include "flooding_endpoint.hpp"
#include "replay_metrics.hpp"
#include "traffic_csv.hpp"

namespace sv = swarmnet::validation;

namespace {

struct Options {
  std::string run_dir;
  std::string output;
  std::string routing = "direct";
  std::string frame_trace;     // CSV of every frame put on the air (empty: none)
  std::string delivery_trace;  // CSV of every message's injection and first delivery
  std::string ip_trace;        // CSV of IP forwards and drops, and of AODV control messages sent
  double duration_s = 0.0;     // 0: summary.json's sim_time_s
  std::uint32_t seed = 1;
  // Propagation and PHY.
  double exponent = 3.0;
  double reference_loss_db = 46.6777;
  double reference_distance_m = 1.0;
  double tx_power_dbm = 27.0531;  // received power at 120 m is -82 dBm with the values above
  double rx_sensitivity_dbm = -101.0;
  double cca_ed_threshold_dbm = -62.0;
  double preamble_min_rssi_dbm = -82.0;
  double preamble_threshold_db = 4.0;
  double noise_figure_db = 7.0;
  std::string error_model = "nist";  // what SwarmNet's sinr PHY implements
  // MAC.
  std::uint32_t rts_threshold_bytes = 65535;
  std::uint32_t queue_packets = 0;  // 0: ns-3's default
  // ARP entries filled in advance: "none" (the default: ARP resolves by request and reply and
  // ns-3's AODV takes the MAC's dropped MPDUs as layer-2 feedback, ns-3's default stack, as users
  // run it), "auto-generated" as NeighborCacheHelper leaves them (no ARP frame, and ns-3's AODV
  // cannot map a neighbour to its MAC address: no layer-2 feedback; what --aligned selects), or
  // "permanent" (no ARP frame, layer-2 feedback as with real ARP).
  std::string arp_entries = "none";
  bool aligned = false;  // --aligned: the configuration aligned with SwarmNet before issue 19
  double queue_max_delay_s = 0.0;  // 0: ns-3's default
  // The queue discipline above the MAC: "fq_codel", which Ipv4AddressHelper::Assign installs
  // (ns-3 as users run it), or "none": the MAC queue is the only queue, as in SwarmNet and the
  // ns-3 engine.
  std::string queue_disc = "fq_codel";
  // Flooding.
  sv::FloodingConfig flooding;
};

// Frames put on the air, by kind (PHY TX begin events).
struct MacCounters {
  std::uint64_t tx_frames = 0;
  std::uint64_t data_frames = 0;
  std::uint64_t ack_frames = 0;
  std::uint64_t other_frames = 0;
  std::uint64_t retries = 0;    // data frames with the Retry bit set
  std::uint64_t rx_errors = 0;  // frames detected but not decoded (SINR too low: collisions)
  std::uint64_t tx_drops = 0;   // frames the MAC gave up (retry limit, queue)
  std::map<std::string, std::uint64_t> dropped_mpdus;  // WifiMac DroppedMpdu events by reason
  std::map<std::string, std::uint64_t> rx_drops;       // PhyRxDrop events by reason
  // MPDUs the MAC's queue discarded before their first transmission, group-addressed ones
  // included (DroppedMpdu above counts unicast ones only, as AODV sees them): "expired" waited
  // longer than WifiMacQueue's MaxDelay, "full" met a queue of MaxSize packets.
  std::uint64_t queue_expired = 0;
  std::uint64_t queue_full = 0;
  // Packets dropped above the MAC: by the queue discipline (fq_codel: CoDel's drops and its
  // overflow), or by the traffic-control layer when there is none and the device is stopped
  // because its MAC queue is full.
  std::uint64_t queue_disc_drops = 0;
  std::uint64_t traffic_control_drops = 0;
};

// ARP (ns-3's default stack, --arp-entries none): messages handed to the MAC (MacTx), their
// frames on the air (PhyTxBegin; a unicast reply is retried like any unicast frame), and the
// packets ARP dropped. ArpL3Protocol's Drop trace fires for a packet arriving while its next
// hop's resolution is pending and the pending queue (3 packets) is full, for a packet to a next
// hop whose entry is dead (resolution failed less than DeadTimeout, 100 s, ago), and for an ARP
// reply nobody waits for; ArpCache's Drop trace for every packet still queued when a resolution
// gives up (MaxRetries requests unanswered). The trace does not say which next hop a dropped
// packet waited for: a drop is put down to a full queue or a dead entry from the node's cache
// (entries pending vs. dead); where the node has both kinds and the packet's own IP destination
// is neither, from the entry of the gateway of AODV's route to that destination, and without one
// (flooding, `direct`, no route) it is counted as ambiguous.
struct ArpCounters {
  std::uint64_t requests = 0;                  // requests handed to the MAC, re-sent ones too
  std::uint64_t replies = 0;                   // replies handed to the MAC (unicast)
  std::uint64_t request_frames = 0;            // on the air
  std::uint64_t reply_frames = 0;              // on the air, retries included
  std::uint64_t queue_full = 0;                // ArpL3Protocol Drop: pending queue full
  std::uint64_t dead_entry = 0;                // ArpL3Protocol Drop: next hop's entry dead
  std::uint64_t queue_full_or_dead_entry = 0;  // ArpL3Protocol Drop: either (see above)
  std::uint64_t unexpected_replies = 0;        // ArpL3Protocol Drop: a reply nobody waited for
  std::uint64_t retries_exhausted = 0;         // ArpCache Drop: resolution given up
  std::map<std::string, std::uint64_t> dropped_by_kind;  // IP packets ARP dropped: data, rreq...
};

struct RoutingCounters {
  std::uint64_t rreq = 0;
  std::uint64_t rrep = 0;
  std::uint64_t hello = 0;
  std::uint64_t rerr = 0;
  std::uint64_t rrep_ack = 0;
  std::uint64_t control_bytes = 0;
  std::uint64_t data_forwards = 0;
  // Breakdown, to compare discovery behaviour with SwarmNet's counters.
  std::uint64_t rreq_originated = 0;  // hop count 0, sent by their originator
  std::map<std::uint32_t, std::uint64_t> rreq_originated_by_ttl;  // IP TTL of each first copy
  std::uint64_t rerr_broadcast = 0;
};

// IP packets dropped (Ipv4L3Protocol Drop), by kind (data: a replayed message; rreq, rrep, rerr,
// rrep_ack: AODV; other: ICMP and the rest), then by reason. ns-3's AODV drops a packet it cannot
// forward as no_route, one that waited in its request queue in vain as route_error; a data packet
// dropped as ttl_expired went round a loop, and so did an AODV message unless it was a TTL-1
// message (RERR, RREP-ACK) sent to a neighbour whose route leads through another node.
using IpDrops = std::map<std::string, std::map<std::string, std::uint64_t>>;

MacCounters g_mac;
ArpCounters g_arp;
RoutingCounters g_routing;
IpDrops g_ip_drops;
constexpr std::uint16_t kAodvPort = 654;
constexpr const char* kSubnetMask = "255.255.0.0";

// The per-frame trace (--frame-trace): one line per PhyTxBegin, so that a run can be compared
// frame by frame with SwarmNet's.
struct FrameTrace {
  std::ofstream out;
  std::map<ns3::Mac48Address, std::uint32_t> node_of;  // MAC address -> node id
  const std::vector<sv::TrafficMessage>* messages = nullptr;
  std::size_t payload_offset = 0;  // bytes of the routing header before the message index
};
FrameTrace g_frame_trace;

// The IP trace (--ip-trace): every forward and drop of a replayed message, and every AODV control
// message sent, so that a message's path and the route discoveries around it can be followed.
struct IpTrace {
  std::ofstream out;
  std::map<ns3::Ipv4Address, std::uint32_t> node_of;  // IPv4 address -> node id
  const std::vector<sv::TrafficMessage>* messages = nullptr;
  std::size_t payload_offset = 0;  // bytes of the routing header before the message index

  [[nodiscard]] std::int64_t node(ns3::Ipv4Address address) const {
    const auto it = node_of.find(address);
    return it == node_of.end() ? std::int64_t{-1} : std::int64_t{it->second};
  }
};
IpTrace g_ip_trace;

// The message id carried by an IP payload (a UDP datagram of the replay), or -1.
std::int64_t datagram_message_id(ns3::Ptr<const ns3::Packet> payload) {
  ns3::Ptr<ns3::Packet> copy = payload->Copy();
  ns3::UdpHeader udp;
  if (copy->RemoveHeader(udp) == 0 || udp.GetDestinationPort() == kAodvPort) return -1;
  std::vector<std::uint8_t> head(g_ip_trace.payload_offset + sv::kMessageIndexBytes);
  const std::uint32_t copied = copy->CopyData(head.data(), static_cast<std::uint32_t>(head.size()));
  if (copied < head.size()) return -1;
  const std::vector<sv::TrafficMessage>& messages = *g_ip_trace.messages;
  const auto index = sv::payload_index(head.data() + g_ip_trace.payload_offset,
                                       sv::kMessageIndexBytes, messages.size());
  return index ? static_cast<std::int64_t>(messages[*index].message_id) : -1;
}

// What an IP payload is: "data" (a replayed message; *message_id is set), an AODV message type,
// or "other".
std::string payload_kind(const ns3::Ipv4Header& header, ns3::Ptr<const ns3::Packet> payload,
                         std::int64_t* message_id) {
  *message_id = -1;
  if (header.GetProtocol() != ns3::UdpL4Protocol::PROT_NUMBER) return "other";
  *message_id = datagram_message_id(payload);
  if (*message_id >= 0) return "data";
  ns3::Ptr<ns3::Packet> copy = payload->Copy();
  ns3::UdpHeader udp;
  copy->RemoveHeader(udp);
  ns3::aodv::TypeHeader type;
  if (udp.GetDestinationPort() != kAodvPort || copy->RemoveHeader(type) == 0 || !type.IsValid()) {
    return "other";
  }
  switch (type.Get()) {
    case ns3::aodv::AODVTYPE_RREQ:
      return "rreq";
    case ns3::aodv::AODVTYPE_RREP:
      return "rrep";
    case ns3::aodv::AODVTYPE_RERR:
      return "rerr";
    case ns3::aodv::AODVTYPE_RREP_ACK:
      return "rrep_ack";
  }
  return "other";
}

void write_ip_event(std::uint32_t node, const char* event, std::int64_t message_id,
                    const ns3::Ipv4Header& ip, const std::string& detail) {
  g_ip_trace.out << ns3::Simulator::Now().GetNanoSeconds() << ',' << node << ',' << event << ','
                 << message_id << ',' << static_cast<int>(ip.GetTtl()) << ','
                 << g_ip_trace.node(ip.GetDestination()) << ',' << detail << '\n';
}

std::string drop_reason_name(ns3::Ipv4L3Protocol::DropReason reason) {
  switch (reason) {
    case ns3::Ipv4L3Protocol::DROP_TTL_EXPIRED:
      return "ttl_expired";
    case ns3::Ipv4L3Protocol::DROP_NO_ROUTE:
      return "no_route";
    case ns3::Ipv4L3Protocol::DROP_BAD_CHECKSUM:
      return "bad_checksum";
    case ns3::Ipv4L3Protocol::DROP_INTERFACE_DOWN:
      return "interface_down";
    case ns3::Ipv4L3Protocol::DROP_ROUTE_ERROR:
      return "route_error";
    case ns3::Ipv4L3Protocol::DROP_FRAGMENT_TIMEOUT:
      return "fragment_timeout";
    case ns3::Ipv4L3Protocol::DROP_DUPLICATE:
      return "duplicate";
  }
  return "other";
}

// What an ARP frame or MAC-layer packet is: 1 a request, 2 a reply, 0 not ARP. `mac_header`:
// the packet starts with its 802.11 header (a frame on the air), else with its LLC/SNAP header
// (a packet handed to the MAC).
constexpr std::uint32_t kArpFrameBytes = 64;  // 802.11 header 24, LLC/SNAP 8, ARP 28, FCS 4
int arp_kind(ns3::Ptr<const ns3::Packet> packet, bool mac_header) {
  ns3::Ptr<ns3::Packet> copy = packet->Copy();
  if (mac_header) {
    ns3::WifiMacHeader mac;
    if (copy->RemoveHeader(mac) == 0 || !mac.IsData()) return 0;
  }
  ns3::LlcSnapHeader llc;
  if (copy->RemoveHeader(llc) == 0 || llc.GetType() != ns3::ArpL3Protocol::PROT_NUMBER) return 0;
  ns3::ArpHeader arp;
  if (copy->RemoveHeader(arp) == 0) return 0;
  return arp.IsRequest() ? 1 : arp.IsReply() ? 2 : 0;
}

// The message index carried by a data frame's UDP payload, or -1 (not a replayed message).
std::int64_t frame_message_index(ns3::Ptr<const ns3::Packet> packet) {
  ns3::Ptr<ns3::Packet> copy = packet->Copy();
  ns3::WifiMacHeader mac;
  ns3::LlcSnapHeader llc;
  ns3::Ipv4Header ip;
  ns3::UdpHeader udp;
  if (copy->RemoveHeader(mac) == 0 || !mac.IsData()) return -1;
  copy->RemoveHeader(llc);
  if (llc.GetType() != ns3::Ipv4L3Protocol::PROT_NUMBER) return -1;
  copy->RemoveHeader(ip);
  if (ip.GetProtocol() != ns3::UdpL4Protocol::PROT_NUMBER) return -1;
  copy->RemoveHeader(udp);
  if (udp.GetDestinationPort() == kAodvPort) return -1;  // AODV's own messages carry no index
  std::vector<std::uint8_t> head(g_frame_trace.payload_offset + sv::kMessageIndexBytes);
  const std::uint32_t copied = copy->CopyData(head.data(), static_cast<std::uint32_t>(head.size()));
  if (copied < head.size()) return -1;
  const auto index = sv::payload_index(head.data() + g_frame_trace.payload_offset,
                                       sv::kMessageIndexBytes, g_frame_trace.messages->size());
  return index ? static_cast<std::int64_t>(*index) : -1;
}

// Columns: time_ns,node,kind,retry,receiver,bytes,sequence,message_id (kind data, arp, ack, rts,
// cts or other; receiver -1: broadcast; message_id -1: none).
void on_phy_tx_begin_traced(std::uint32_t node, ns3::Ptr<const ns3::Packet> packet,
                            double /*power_w*/) {
  ns3::WifiMacHeader header;
  std::string kind = "other";
  int retry = 0;
  std::int64_t receiver = -1;
  std::int64_t sequence = -1;
  std::int64_t message_id = -1;
  if (packet->PeekHeader(header) != 0) {
    if (header.IsData()) {
      kind = packet->GetSize() == kArpFrameBytes && arp_kind(packet, true) != 0 ? "arp" : "data";
      retry = header.IsRetry() ? 1 : 0;
      sequence = header.GetSequenceNumber();
      const std::int64_t index = frame_message_index(packet);
      if (index >= 0) {
        message_id = static_cast<std::int64_t>(
            (*g_frame_trace.messages)[static_cast<std::size_t>(index)].message_id);
      }
    } else if (header.IsAck()) {
      kind = "ack";
    } else if (header.IsRts()) {
      kind = "rts";
    } else if (header.IsCts()) {
      kind = "cts";
    }
    const auto to = g_frame_trace.node_of.find(header.GetAddr1());
    if (to != g_frame_trace.node_of.end()) receiver = to->second;
  }
  g_frame_trace.out << ns3::Simulator::Now().GetNanoSeconds() << ',' << node << ',' << kind << ','
                    << retry << ',' << receiver << ',' << packet->GetSize() << ',' << sequence
                    << ',' << message_id << '\n';
}

void on_phy_tx_begin(ns3::Ptr<const ns3::Packet> packet, double /*power_w*/) {
  ++g_mac.tx_frames;
  ns3::WifiMacHeader header;
  if (packet->PeekHeader(header) == 0) {
    ++g_mac.other_frames;
  } else if (header.IsData()) {
    ++g_mac.data_frames;
    if (header.IsRetry()) ++g_mac.retries;
    // Only a frame of an ARP message's size is looked into: the count costs nothing on the rest.
    if (packet->GetSize() == kArpFrameBytes) {
      const int arp = arp_kind(packet, true);
      if (arp == 1) ++g_arp.request_frames;
      if (arp == 2) ++g_arp.reply_frames;
    }
  } else if (header.IsAck()) {
    ++g_mac.ack_frames;
  } else {
    ++g_mac.other_frames;
  }
}

void on_phy_rx_drop(ns3::Ptr<const ns3::Packet> /*packet*/, ns3::WifiPhyRxfailureReason reason) {
  std::ostringstream name;
  name << reason;
  ++g_mac.rx_drops[name.str()];
}

void on_phy_rx_error(ns3::Ptr<const ns3::Packet> /*packet*/, double /*snr*/) { ++g_mac.rx_errors; }

void on_mac_tx_drop(ns3::Ptr<const ns3::Packet> /*packet*/) { ++g_mac.tx_drops; }

// Every packet handed to the MAC, behind its LLC/SNAP header: ARP requests and replies counted.
void on_mac_tx(ns3::Ptr<const ns3::Packet> packet) {
  ns3::LlcSnapHeader llc;
  if (packet->PeekHeader(llc) == 0 || llc.GetType() != ns3::ArpL3Protocol::PROT_NUMBER) return;
  const int arp = arp_kind(packet, false);
  if (arp == 1) ++g_arp.requests;
  if (arp == 2) ++g_arp.replies;
}

// For the ARP drop sinks: every node's ARP cache on its wireless interface, every node's address
// (the next hops a cache can hold) and, under AODV, every node's routing protocol.
struct ArpState {
  std::vector<ns3::Ptr<ns3::ArpCache>> cache_of_node;
  std::vector<ns3::Ipv4Address> addresses;
  std::vector<ns3::Ptr<ns3::Ipv4RoutingProtocol>> aodv_of_node;
};
ArpState g_arp_state;

// The kind of an IP packet ARP dropped (it carries its IPv4 header): "data", an AODV message type
// or "other"; "" if it is no IP packet. *ip is its IPv4 header, *message_id as payload_kind's.
std::string arp_dropped_kind(ns3::Ptr<const ns3::Packet> packet, ns3::Ipv4Header* ip,
                             std::int64_t* message_id) {
  *message_id = -1;
  if (packet->GetSize() < 20) return "";
  ns3::Ptr<ns3::Packet> copy = packet->Copy();
  if (copy->RemoveHeader(*ip) == 0) return "";
  return payload_kind(*ip, copy, message_id);
}

// With --ip-trace, a packet ARP dropped: "arp_drop" for a replayed message, "arp_drop_<kind>" for
// anything else; the detail is the reason as counted in ArpCounters.
void trace_arp_drop(std::uint32_t node, const std::string& kind, std::int64_t message_id,
                    const ns3::Ipv4Header& ip, const char* reason) {
  if (!g_ip_trace.out.is_open()) return;
  const std::string event = kind == "data" ? "arp_drop" : "arp_drop_" + kind;
  write_ip_event(node, event.c_str(), message_id, ip, reason);
}

// The gateway of `node`'s AODV route to `destination`, or nullopt without AODV or such a route.
// PrintRoutingTable is AODV's only public view of its table; it prints a purged copy and leaves
// the protocol as it was.
std::optional<ns3::Ipv4Address> aodv_gateway(std::uint32_t node, ns3::Ipv4Address destination) {
  if (g_arp_state.aodv_of_node.empty()) return std::nullopt;
  std::ostringstream table;
  g_arp_state.aodv_of_node[node]->PrintRoutingTable(ns3::Create<ns3::OutputStreamWrapper>(&table));
  std::ostringstream wanted;
  wanted << destination;
  std::istringstream lines(table.str());
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string route_destination;
    std::string gateway;
    if (fields >> route_destination >> gateway && route_destination == wanted.str()) {
      return ns3::Ipv4Address(gateway.c_str());
    }
  }
  return std::nullopt;
}

// ArpL3Protocol Drop at `node` (see ArpCounters).
void on_arp_l3_drop(std::uint32_t node, ns3::Ptr<const ns3::Packet> packet) {
  ns3::Ipv4Header ip;
  std::int64_t message_id = -1;
  const std::string kind = arp_dropped_kind(packet, &ip, &message_id);
  const ns3::Ipv4Address destination = ip.GetDestination();
  if (kind.empty()) {
    ++g_arp.unexpected_replies;
    return;
  }
  ++g_arp.dropped_by_kind[kind];
  const ns3::Ptr<ns3::ArpCache> cache = g_arp_state.cache_of_node[node];
  bool pending = false;
  bool dead = false;
  for (const ns3::Ipv4Address& address : g_arp_state.addresses) {
    ns3::ArpCache::Entry* entry = cache->Lookup(address);
    if (entry == nullptr || entry->IsExpired()) continue;
    pending = pending || entry->IsWaitReply();
    dead = dead || entry->IsDead();
  }
  // The packet's next hop: its IP destination if that is a neighbour ARP knows of, else (both
  // kinds of entry present) the gateway of AODV's route to that destination.
  ns3::ArpCache::Entry* own = cache->Lookup(destination);
  if ((own == nullptr || own->IsExpired()) && pending && dead) {
    if (const auto gateway = aodv_gateway(node, destination)) own = cache->Lookup(*gateway);
  }
  const bool own_pending = own != nullptr && !own->IsExpired() && own->IsWaitReply();
  const bool own_dead = own != nullptr && !own->IsExpired() && own->IsDead();
  if (pending && (!dead || own_pending)) {
    ++g_arp.queue_full;
    trace_arp_drop(node, kind, message_id, ip, "queue_full");
  } else if (dead && (!pending || own_dead)) {
    ++g_arp.dead_entry;
    trace_arp_drop(node, kind, message_id, ip, "dead_entry");
  } else {
    ++g_arp.queue_full_or_dead_entry;
    trace_arp_drop(node, kind, message_id, ip, "queue_full_or_dead_entry");
  }
}

// ArpCache Drop at `node`: a packet still queued when its resolution gave up.
void on_arp_cache_drop(std::uint32_t node, ns3::Ptr<const ns3::Packet> packet) {
  ++g_arp.retries_exhausted;
  ns3::Ipv4Header ip;
  std::int64_t message_id = -1;
  const std::string kind = arp_dropped_kind(packet, &ip, &message_id);
  ++g_arp.dropped_by_kind[kind.empty() ? "other" : kind];
  if (!kind.empty()) trace_arp_drop(node, kind, message_id, ip, "retries_exhausted");
}

// The MAC's DroppedMpdu trace is what ns-3's AODV takes as layer-2 feedback (a unicast MPDU
// dropped for any reason closes the link to its receiver).
void on_dropped_mpdu(ns3::WifiMacDropReason reason, ns3::Ptr<const ns3::WifiMpdu> mpdu) {
  if (mpdu->GetHeader().GetAddr1().IsGroup()) return;
  switch (reason) {
    case ns3::WIFI_MAC_DROP_FAILED_ENQUEUE:
      ++g_mac.dropped_mpdus["failed_enqueue"];
      break;
    case ns3::WIFI_MAC_DROP_EXPIRED_LIFETIME:
      ++g_mac.dropped_mpdus["expired_lifetime"];
      break;
    case ns3::WIFI_MAC_DROP_REACHED_RETRY_LIMIT:
      ++g_mac.dropped_mpdus["retry_limit"];
      break;
    case ns3::WIFI_MAC_DROP_QOS_OLD_PACKET:
      ++g_mac.dropped_mpdus["qos_old_packet"];
      break;
  }
}

void on_queue_expired(ns3::Ptr<const ns3::WifiMpdu> /*mpdu*/) { ++g_mac.queue_expired; }
void on_queue_full(ns3::Ptr<const ns3::WifiMpdu> /*mpdu*/) { ++g_mac.queue_full; }
void on_queue_disc_drop(ns3::Ptr<const ns3::QueueDiscItem> /*item*/) { ++g_mac.queue_disc_drops; }
void on_traffic_control_drop(ns3::Ptr<const ns3::Packet> /*packet*/) {
  ++g_mac.traffic_control_drops;
}

// Every IP packet sent on a wireless interface: AODV control packets are counted by type.
void on_ip_tx(ns3::Ptr<const ns3::Packet> packet, ns3::Ptr<ns3::Ipv4> ipv4,
              std::uint32_t interface) {
  if (interface == 0) return;  // loopback
  ns3::Ptr<ns3::Packet> copy = packet->Copy();
  ns3::Ipv4Header ip;
  copy->RemoveHeader(ip);
  if (ip.GetProtocol() != ns3::UdpL4Protocol::PROT_NUMBER) return;
  ns3::UdpHeader udp;
  copy->RemoveHeader(udp);
  if (udp.GetDestinationPort() != kAodvPort) return;
  ns3::aodv::TypeHeader type;
  copy->RemoveHeader(type);
  if (!type.IsValid()) return;
  g_routing.control_bytes += packet->GetSize();
  const bool traced = g_ip_trace.out.is_open();
  const std::uint32_t node = traced ? ipv4->GetObject<ns3::Node>()->GetId() : 0;
  std::ostringstream detail;
  // A unicast AODV message goes to a neighbour through IP, along AODV's own route to it: where
  // that route leads through another node, that node relays the datagram as IP.
  if (traced && g_ip_trace.node(ip.GetSource()) != node) {
    detail << "ip relay of " << g_ip_trace.node(ip.GetSource()) << ": ";
  }
  switch (type.Get()) {
    case ns3::aodv::AODVTYPE_RREQ: {
      ++g_routing.rreq;
      ns3::aodv::RreqHeader rreq;
      copy->RemoveHeader(rreq);
      if (rreq.GetHopCount() == 0 && rreq.GetOrigin() == ip.GetSource()) {
        ++g_routing.rreq_originated;
        ++g_routing.rreq_originated_by_ttl[ip.GetTtl()];
      }
      if (traced) {
        detail << "origin " << g_ip_trace.node(rreq.GetOrigin()) << " seq " << rreq.GetOriginSeqno()
               << " id " << rreq.GetId() << " dst " << g_ip_trace.node(rreq.GetDst()) << " dst_seq "
               << (rreq.GetUnknownSeqno() ? std::string("unknown")
                                          : std::to_string(rreq.GetDstSeqno()))
               << " hops " << static_cast<int>(rreq.GetHopCount());
        write_ip_event(node, "rreq", -1, ip, detail.str());
      }
      break;
    }
    case ns3::aodv::AODVTYPE_RREP: {
      ns3::aodv::RrepHeader rrep;
      copy->RemoveHeader(rrep);
      // ns-3 sends HELLO as an RREP for itself, hop count 0, to the broadcast address; an RREP
      // answering an RREQ goes to a next hop.
      const ns3::Ipv4Address to = ip.GetDestination();
      const bool broadcast =
          to.IsBroadcast() || to.IsSubnetDirectedBroadcast(ns3::Ipv4Mask(kSubnetMask));
      const bool hello = broadcast && rrep.GetDst() == ip.GetSource() && rrep.GetHopCount() == 0;
      ++(hello ? g_routing.hello : g_routing.rrep);
      if (traced) {
        detail << "dst " << g_ip_trace.node(rrep.GetDst()) << " dst_seq " << rrep.GetDstSeqno()
               << " origin " << g_ip_trace.node(rrep.GetOrigin()) << " hops "
               << static_cast<int>(rrep.GetHopCount()) << " lifetime_ms "
               << rrep.GetLifeTime().GetMilliSeconds();
        write_ip_event(node, hello ? "hello" : "rrep", -1, ip, detail.str());
      }
      break;
    }
    case ns3::aodv::AODVTYPE_RERR: {
      ++g_routing.rerr;
      const ns3::Ipv4Address to = ip.GetDestination();
      if (to.IsBroadcast() || to.IsSubnetDirectedBroadcast(ns3::Ipv4Mask(kSubnetMask))) {
        ++g_routing.rerr_broadcast;
      }
      if (traced) {
        ns3::aodv::RerrHeader rerr;
        copy->RemoveHeader(rerr);
        std::pair<ns3::Ipv4Address, std::uint32_t> unreachable;
        for (const char* separator = ""; rerr.RemoveUnDestination(unreachable); separator = "; ") {
          detail << separator << "dst " << g_ip_trace.node(unreachable.first) << " seq "
                 << unreachable.second;
        }
        write_ip_event(node, "rerr", -1, ip, detail.str());
      }
      break;
    }
    case ns3::aodv::AODVTYPE_RREP_ACK:
      ++g_routing.rrep_ack;
      break;
  }
}

void on_unicast_forward(const ns3::Ipv4Header& /*header*/, ns3::Ptr<const ns3::Packet> /*p*/,
                        std::uint32_t /*interface*/) {
  ++g_routing.data_forwards;
}

void on_unicast_forward_traced(std::uint32_t node, const ns3::Ipv4Header& header,
                               ns3::Ptr<const ns3::Packet> payload, std::uint32_t /*interface*/) {
  const std::int64_t message_id = datagram_message_id(payload);
  if (message_id >= 0) write_ip_event(node, "forward", message_id, header, "");
}

// IP drops by kind and reason; with --ip-trace, every drop too ("drop" for a replayed message,
// "drop_<kind>" for anything else).
void on_ip_drop(const ns3::Ipv4Header& header, ns3::Ptr<const ns3::Packet> payload,
                ns3::Ipv4L3Protocol::DropReason reason, ns3::Ptr<ns3::Ipv4> ipv4,
                std::uint32_t /*interface*/) {
  const std::string name = drop_reason_name(reason);
  std::int64_t message_id = -1;
  const std::string kind = payload_kind(header, payload, &message_id);
  ++g_ip_drops[kind][name];
  if (g_ip_trace.out.is_open()) {
    const std::string event = kind == "data" ? "drop" : "drop_" + kind;
    write_ip_event(ipv4->GetObject<ns3::Node>()->GetId(), event.c_str(), message_id, header, name);
  }
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

// Nodes in an ns-2 mobility trace: one more than the largest $node_(i).
std::uint32_t count_nodes(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the mobility trace");
  std::string line;
  std::int64_t largest = -1;
  const std::string marker = "$node_(";
  while (std::getline(in, line)) {
    const std::size_t at = line.find(marker);
    if (at == std::string::npos) continue;
    largest = std::max<std::int64_t>(largest, std::stoll(line.substr(at + marker.size())));
  }
  if (largest < 0) throw std::runtime_error(path + ": no node in the mobility trace");
  return static_cast<std::uint32_t>(largest + 1);
}

double summary_duration_s(const std::string& run_dir) {
  std::ifstream in(run_dir + "/summary.json");
  if (!in) {
    throw std::runtime_error(run_dir + "/summary.json: cannot open it; give --duration-s instead");
  }
  const nlohmann::json summary = nlohmann::json::parse(in);
  return summary.at("sim_time_s").get<double>();
}

ns3::NetDeviceContainer install_wifi(const Options& options, const ns3::NodeContainer& nodes) {
  ns3::YansWifiChannelHelper channel;
  channel.SetPropagationDelay("ns3::ConstantSpeedPropagationDelayModel");
  channel.AddPropagationLoss("ns3::LogDistancePropagationLossModel", "Exponent",
                             ns3::DoubleValue(options.exponent), "ReferenceDistance",
                             ns3::DoubleValue(options.reference_distance_m), "ReferenceLoss",
                             ns3::DoubleValue(options.reference_loss_db));

  ns3::YansWifiPhyHelper phy;
  phy.SetChannel(channel.Create());
  phy.Set("TxPowerStart", ns3::DoubleValue(options.tx_power_dbm));
  phy.Set("TxPowerEnd", ns3::DoubleValue(options.tx_power_dbm));
  phy.Set("RxSensitivity", ns3::DoubleValue(options.rx_sensitivity_dbm));
  phy.Set("CcaEdThreshold", ns3::DoubleValue(options.cca_ed_threshold_dbm));
  phy.Set("RxNoiseFigure", ns3::DoubleValue(options.noise_figure_db));
  phy.SetPreambleDetectionModel("ns3::ThresholdPreambleDetectionModel", "MinimumRssi",
                                ns3::DoubleValue(options.preamble_min_rssi_dbm), "Threshold",
                                ns3::DoubleValue(options.preamble_threshold_db));
  if (options.error_model == "nist") {
    phy.SetErrorRateModel("ns3::NistErrorRateModel");
  } else if (options.error_model == "yans") {
    phy.SetErrorRateModel("ns3::YansErrorRateModel");
  } else {
    phy.SetErrorRateModel("ns3::TableBasedErrorRateModel");
  }

  ns3::WifiHelper wifi;
  wifi.SetStandard(ns3::WIFI_STANDARD_80211a);
  wifi.SetRemoteStationManager("ns3::ConstantRateWifiManager", "DataMode",
                               ns3::StringValue("OfdmRate6Mbps"), "ControlMode",
                               ns3::StringValue("OfdmRate6Mbps"), "RtsCtsThreshold",
                               ns3::UintegerValue(options.rts_threshold_bytes));
  ns3::WifiMacHelper mac;
  mac.SetType("ns3::AdhocWifiMac");
  return wifi.Install(phy, mac, nodes);
}

// NeighborCacheHelper marks its entries auto-generated, and ns-3.37's AODV
// (Neighbors::LookupMacAddress) only takes the MAC address of an entry that is alive or
// permanent: with auto-generated entries every neighbour keeps the null MAC address, the MAC's
// DroppedMpdu reports match no neighbour, and AODV loses its layer-2 link-break detection,
// which it has in any run where ARP resolved the neighbour (entries alive for 120 s). Permanent
// entries give it back and change nothing else: ARP sends to permanent and auto-generated
// entries alike, and neither expires.
void make_arp_entries_permanent(const ns3::NodeContainer& nodes,
                                const ns3::Ipv4InterfaceContainer& interfaces) {
  for (std::uint32_t i = 0; i < nodes.GetN(); ++i) {
    ns3::Ptr<ns3::Ipv4L3Protocol> ip = nodes.Get(i)->GetObject<ns3::Ipv4L3Protocol>();
    const ns3::Ptr<ns3::ArpCache> cache = ip->GetInterface(interfaces.Get(i).second)->GetArpCache();
    for (std::uint32_t j = 0; j < interfaces.GetN(); ++j) {
      ns3::ArpCache::Entry* entry = cache->Lookup(interfaces.GetAddress(j));
      if (entry != nullptr && entry->IsAutoGenerated()) entry->MarkPermanent();
    }
  }
}

nlohmann::ordered_json run(const Options& options) {
  const std::string mobility_path = options.run_dir + "/mobility.ns2";
  const std::string traffic_path = options.run_dir + "/traffic.csv";
  const double duration_s =
      options.duration_s > 0.0 ? options.duration_s : summary_duration_s(options.run_dir);
  const std::uint32_t node_count = count_nodes(mobility_path);
  const std::vector<sv::TrafficMessage> messages = sv::read_traffic_csv(traffic_path);
  for (const sv::TrafficMessage& message : messages) {
    if (message.payload_bytes < sv::kMessageIndexBytes) {
      throw std::runtime_error(traffic_path + ": message " + std::to_string(message.message_id) +
                               " has fewer than 4 payload bytes; the replay needs 4");
    }
    if (message.source >= node_count ||
        (!message.broadcast() && message.destination >= node_count)) {
      throw std::runtime_error(traffic_path + ": message " + std::to_string(message.message_id) +
                               " names a robot that the mobility trace does not have");
    }
  }

  ns3::RngSeedManager::SetSeed(1);
  ns3::RngSeedManager::SetRun(options.seed);
  if (options.queue_packets > 0) {
    ns3::Config::SetDefault(
        "ns3::WifiMacQueue::MaxSize",
        ns3::QueueSizeValue(ns3::QueueSize(ns3::QueueSizeUnit::PACKETS, options.queue_packets)));
  }
  if (options.queue_max_delay_s > 0.0) {
    ns3::Config::SetDefault("ns3::WifiMacQueue::MaxDelay",
                            ns3::TimeValue(ns3::Seconds(options.queue_max_delay_s)));
  }

  ns3::NodeContainer nodes;
  nodes.Create(node_count);
  const ns3::NetDeviceContainer devices = install_wifi(options, nodes);
  ns3::Ns2MobilityHelper(mobility_path).Install();

  ns3::InternetStackHelper internet;
  ns3::AodvHelper aodv;
  if (options.routing == "aodv") internet.SetRoutingHelper(aodv);
  internet.Install(nodes);
  ns3::Ipv4AddressHelper addresses;
  addresses.SetBase("10.1.0.0", kSubnetMask);
  const ns3::Ipv4InterfaceContainer interfaces = addresses.Assign(devices);
  // Assign has put fq_codel above each device's MAC queue, with flow control: the device stops
  // taking packets while its MAC queue is full, and they wait (or are dropped by CoDel) above it.
  if (options.queue_disc == "none") ns3::TrafficControlHelper().Uninstall(devices);
  // By default (`none`) ARP runs as ns-3 users run it: requests and replies on the air, packets
  // queued (3 at most) behind a pending resolution, and ns-3's AODV mapping its neighbours to MAC
  // addresses from the alive entries, so that the MAC's DroppedMpdu reports break links. The
  // aligned setup (`auto-generated`, --aligned) fills every cache before the run: no ARP frame,
  // as in SwarmNet's `network.arp: static`, and no layer-2 feedback for ns-3's AODV.
  if (options.arp_entries != "none") ns3::NeighborCacheHelper().PopulateNeighborCache();
  if (options.arp_entries == "permanent") make_arp_entries_permanent(nodes, interfaces);
  for (std::uint32_t i = 0; i < node_count; ++i) {
    g_arp_state.addresses.push_back(interfaces.GetAddress(i));
    const ns3::Ptr<ns3::Node> node = nodes.Get(i);
    g_arp_state.cache_of_node.push_back(node->GetObject<ns3::Ipv4L3Protocol>()
                                            ->GetInterface(interfaces.Get(i).second)
                                            ->GetArpCache());
    node->GetObject<ns3::ArpL3Protocol>()->TraceConnectWithoutContext(
        "Drop", ns3::MakeBoundCallback(&on_arp_l3_drop, i));
    g_arp_state.cache_of_node.back()->TraceConnectWithoutContext(
        "Drop", ns3::MakeBoundCallback(&on_arp_cache_drop, i));
    if (options.routing == "aodv") {
      g_arp_state.aodv_of_node.push_back(node->GetObject<ns3::Ipv4>()->GetRoutingProtocol());
    }
  }

  std::int64_t stream = 1000;
  stream += ns3::WifiHelper().AssignStreams(devices, stream);
  if (options.routing == "aodv") stream += aodv.AssignStreams(nodes, stream);

  sv::ReplayMetrics metrics(messages);
  sv::ReplayWorld world{messages, metrics, {}, 9};
  for (std::uint32_t i = 0; i < node_count; ++i)
    world.addresses.push_back(interfaces.GetAddress(i));
  sv::FloodingCounters flooding_counters;
  std::vector<std::unique_ptr<sv::ReplayEndpoint>> endpoints;
  for (std::uint32_t i = 0; i < node_count; ++i) {
    if (options.routing == "flooding") {
      auto jitter = ns3::CreateObject<ns3::UniformRandomVariable>();
      jitter->SetStream(stream++);
      endpoints.push_back(std::make_unique<sv::FloodingEndpoint>(
          nodes.Get(i), i, world, options.flooding, flooding_counters, jitter));
    } else {
      endpoints.push_back(std::make_unique<sv::DatagramEndpoint>(nodes.Get(i), i, world));
    }
  }
  for (std::uint32_t index = 0; index < messages.size(); ++index) {
    const sv::TrafficMessage& message = messages[index];
    sv::ReplayEndpoint* endpoint = endpoints[message.source].get();
    ns3::Simulator::ScheduleWithContext(message.source, ns3::NanoSeconds(message.inject_ns),
                                        [endpoint, index]() { endpoint->send(index); });
  }

  ns3::Config::ConnectWithoutContext("/NodeList/*/DeviceList/*/$ns3::WifiNetDevice/Phy/PhyTxBegin",
                                     ns3::MakeCallback(&on_phy_tx_begin));
  ns3::Config::ConnectWithoutContext("/NodeList/*/DeviceList/*/$ns3::WifiNetDevice/Phy/PhyRxDrop",
                                     ns3::MakeCallback(&on_phy_rx_drop));
  ns3::Config::ConnectWithoutContext(
      "/NodeList/*/DeviceList/*/$ns3::WifiNetDevice/Phy/State/RxError",
      ns3::MakeCallback(&on_phy_rx_error));
  ns3::Config::ConnectWithoutContext("/NodeList/*/DeviceList/*/$ns3::WifiNetDevice/Mac/MacTxDrop",
                                     ns3::MakeCallback(&on_mac_tx_drop));
  ns3::Config::ConnectWithoutContext("/NodeList/*/DeviceList/*/$ns3::WifiNetDevice/Mac/MacTx",
                                     ns3::MakeCallback(&on_mac_tx));
  ns3::Config::ConnectWithoutContext("/NodeList/*/DeviceList/*/$ns3::WifiNetDevice/Mac/DroppedMpdu",
                                     ns3::MakeCallback(&on_dropped_mpdu));
  for (std::uint32_t i = 0; i < node_count; ++i) {
    const auto wifi = ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(i));
    const ns3::Ptr<ns3::WifiMacQueue> queue = wifi->GetMac()->GetTxop()->GetWifiMacQueue();
    queue->TraceConnectWithoutContext("Expired", ns3::MakeCallback(&on_queue_expired));
    queue->TraceConnectWithoutContext("DropBeforeEnqueue", ns3::MakeCallback(&on_queue_full));
    const ns3::Ptr<ns3::TrafficControlLayer> traffic_control =
        nodes.Get(i)->GetObject<ns3::TrafficControlLayer>();
    traffic_control->TraceConnectWithoutContext("TcDrop",
                                                ns3::MakeCallback(&on_traffic_control_drop));
    const ns3::Ptr<ns3::QueueDisc> queue_disc =
        traffic_control->GetRootQueueDiscOnDevice(devices.Get(i));
    if (queue_disc != nullptr) {
      queue_disc->TraceConnectWithoutContext("Drop", ns3::MakeCallback(&on_queue_disc_drop));
    }
  }
  ns3::Config::ConnectWithoutContext("/NodeList/*/$ns3::Ipv4L3Protocol/Tx",
                                     ns3::MakeCallback(&on_ip_tx));
  ns3::Config::ConnectWithoutContext("/NodeList/*/$ns3::Ipv4L3Protocol/UnicastForward",
                                     ns3::MakeCallback(&on_unicast_forward));
  g_ip_trace.messages = &messages;
  if (options.routing == "flooding") g_ip_trace.payload_offset = sv::FloodingEndpoint::kHeaderBytes;
  ns3::Config::ConnectWithoutContext("/NodeList/*/$ns3::Ipv4L3Protocol/Drop",
                                     ns3::MakeCallback(&on_ip_drop));
  if (!options.ip_trace.empty()) {
    g_ip_trace.out.open(options.ip_trace);
    if (!g_ip_trace.out) throw std::runtime_error(options.ip_trace + ": cannot write");
    g_ip_trace.out << "time_ns,node,event,message_id,ip_ttl,ip_destination,detail\n";
    for (std::uint32_t i = 0; i < node_count; ++i) {
      g_ip_trace.node_of[interfaces.GetAddress(i)] = i;
      nodes.Get(i)->GetObject<ns3::Ipv4L3Protocol>()->TraceConnectWithoutContext(
          "UnicastForward", ns3::MakeBoundCallback(&on_unicast_forward_traced, i));
    }
  }

  if (!options.frame_trace.empty()) {
    g_frame_trace.out.open(options.frame_trace);
    if (!g_frame_trace.out) throw std::runtime_error(options.frame_trace + ": cannot write");
    g_frame_trace.out << "time_ns,node,kind,retry,receiver,bytes,sequence,message_id\n";
    g_frame_trace.messages = &messages;
    if (options.routing == "flooding") {
      g_frame_trace.payload_offset = sv::FloodingEndpoint::kHeaderBytes;
    }
    for (std::uint32_t i = 0; i < node_count; ++i) {
      g_frame_trace.node_of[ns3::Mac48Address::ConvertFrom(devices.Get(i)->GetAddress())] = i;
      const auto wifi = ns3::DynamicCast<ns3::WifiNetDevice>(devices.Get(i));
      wifi->GetPhy()->TraceConnectWithoutContext(
          "PhyTxBegin", ns3::MakeBoundCallback(&on_phy_tx_begin_traced, i));
    }
  }

  ns3::Simulator::Stop(ns3::Seconds(duration_s));
  const auto wall_start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  ns3::Simulator::Run();
  const double cpu_s = process_cpu_seconds() - cpu_start;
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  ns3::Simulator::Destroy();
  if (g_frame_trace.out.is_open()) g_frame_trace.out.close();
  if (g_ip_trace.out.is_open()) g_ip_trace.out.close();
  if (!options.delivery_trace.empty()) {
    std::ofstream deliveries(options.delivery_trace);
    metrics.write_deliveries(deliveries);
    if (!deliveries) throw std::runtime_error(options.delivery_trace + ": cannot write");
  }

  using Json = nlohmann::ordered_json;
  Json out;
  out["simulator"] = "ns-3.37";
  out["run_dir"] = options.run_dir;
  out["routing_plugin"] = options.routing;
  out["seed"] = options.seed;
  out["robots"] = node_count;
  out["sim_time_s"] = duration_s;
  const Json measures = metrics.report();
  for (const auto& [key, value] : measures.items()) out[key] = value;
  // tx_frames counts every frame on the air, ARP's included (data_frames too: an ARP message
  // goes as a data frame).
  out["mac"] = {{"tx_frames", g_mac.tx_frames},
                {"data_frames", g_mac.data_frames},
                {"arp_frames", g_arp.request_frames + g_arp.reply_frames},
                {"ack_frames", g_mac.ack_frames},
                {"other_frames", g_mac.other_frames},
                {"retries", g_mac.retries},
                {"rx_errors", g_mac.rx_errors},
                {"tx_drops", g_mac.tx_drops},
                {"rx_drops", g_mac.rx_drops},
                {"dropped_unicast_mpdus", g_mac.dropped_mpdus},
                {"queue_drops",
                 {{"expired", g_mac.queue_expired},
                  {"full", g_mac.queue_full},
                  {"queue_disc", g_mac.queue_disc_drops},
                  {"traffic_control", g_mac.traffic_control_drops}}},
                {"queue_disc", options.queue_disc}};
  const std::uint64_t arp_packet_drops = g_arp.queue_full + g_arp.dead_entry +
                                         g_arp.queue_full_or_dead_entry + g_arp.retries_exhausted;
  out["arp"] = {{"entries", options.arp_entries},
                {"requests_sent", g_arp.requests},
                {"replies_sent", g_arp.replies},
                {"request_frames", g_arp.request_frames},
                {"reply_frames", g_arp.reply_frames},
                {"drops",
                 {{"queue_full", g_arp.queue_full},
                  {"dead_entry", g_arp.dead_entry},
                  {"queue_full_or_dead_entry", g_arp.queue_full_or_dead_entry},
                  {"retries_exhausted", g_arp.retries_exhausted},
                  {"unexpected_replies", g_arp.unexpected_replies}}},
                {"packets_dropped", arp_packet_drops},
                {"dropped_by_kind", g_arp.dropped_by_kind}};
  out["ip_drops"] = g_ip_drops;
  if (options.routing == "aodv") {
    nlohmann::ordered_json by_ttl = nlohmann::ordered_json::object();
    for (const auto& [ttl, count] : g_routing.rreq_originated_by_ttl) {
      by_ttl[std::to_string(ttl)] = count;
    }
    const std::uint64_t control =
        g_routing.rreq + g_routing.rrep + g_routing.hello + g_routing.rerr + g_routing.rrep_ack;
    out["routing"] = {{"control_packets", control},
                      {"control_bytes", g_routing.control_bytes},
                      {"rreq", g_routing.rreq},
                      {"rrep", g_routing.rrep},
                      {"hello", g_routing.hello},
                      {"rerr", g_routing.rerr},
                      {"rrep_ack", g_routing.rrep_ack},
                      {"data_forwards", g_routing.data_forwards},
                      {"rreq_originated", g_routing.rreq_originated},
                      {"rreq_originated_by_ttl", by_ttl},
                      {"rerr_broadcast", g_routing.rerr_broadcast}};
  } else if (options.routing == "flooding") {
    out["routing"] = {{"control_packets", 0},
                      {"data_forwards", flooding_counters.forwards},
                      {"duplicates", flooding_counters.duplicates},
                      {"ttl_expired", flooding_counters.ttl_expired}};
  } else {
    out["routing"] = {{"control_packets", 0}, {"data_forwards", 0}};
  }
  out["cpu_s"] = {{"network", cpu_s}};
  out["wall_s"] = wall_s;
  out["parameters"] = {{"standard", "802.11a"},
                       {"rate", "OfdmRate6Mbps (data and control)"},
                       {"exponent", options.exponent},
                       {"reference_loss_db", options.reference_loss_db},
                       {"reference_distance_m", options.reference_distance_m},
                       {"tx_power_dbm", options.tx_power_dbm},
                       {"rx_sensitivity_dbm", options.rx_sensitivity_dbm},
                       {"cca_ed_threshold_dbm", options.cca_ed_threshold_dbm},
                       {"preamble_min_rssi_dbm", options.preamble_min_rssi_dbm},
                       {"preamble_threshold_db", options.preamble_threshold_db},
                       {"noise_figure_db", options.noise_figure_db},
                       {"error_model", options.error_model},
                       {"rts_threshold_bytes", options.rts_threshold_bytes},
                       {"arp_entries", options.arp_entries},
                       {"aligned", options.aligned},
                       {"aodv_layer2_feedback", options.arp_entries != "auto-generated"},
                       {"flooding_ttl", options.flooding.ttl},
                       {"flooding_jitter_max_s", options.flooding.jitter_max_s},
                       {"flooding_cache_size", options.flooding.cache_size}};
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Replays a SwarmNet run's mobility trace and traffic schedule in ns-3.37 "
      "(802.11a at 6 Mbps, log-distance propagation) and writes its measures as JSON. By "
      "default ns-3 runs as its users run it: ARP by request and reply, AODV with the MAC's "
      "layer-2 feedback; --aligned gives the setup aligned with SwarmNet's own engine (ARP "
      "filled in advance, no layer-2 feedback)"};
  app.add_option("run_dir", options.run_dir,
                 "SwarmNet run directory: mobility.ns2, traffic.csv (and summary.json)")
      ->required()
      ->check(CLI::ExistingDirectory);
  app.add_option("-o,--output", options.output, "JSON result file (default: standard output)");
  app.add_option("--routing", options.routing, "routing protocol")
      ->check(CLI::IsMember({"direct", "flooding", "aodv"}))
      ->capture_default_str();
  app.add_option("--frame-trace", options.frame_trace,
                 "CSV file of every frame put on the air (PhyTxBegin): "
                 "time_ns,node,kind,retry,receiver,bytes,sequence,message_id");
  app.add_option("--delivery-trace", options.delivery_trace,
                 "CSV file of every message: message_id,source,destination,inject_ns,"
                 "delivered_ns (-1: not delivered)");
  app.add_option("--ip-trace", options.ip_trace,
                 "CSV file of every IP forward and drop of a message, every packet ARP "
                 "dropped (event arp_drop, detail the reason) and every AODV control "
                 "message sent: time_ns,node,event,message_id,ip_ttl,ip_destination,detail "
                 "(ip_destination -1: broadcast)");
  app.add_option("--duration-s", options.duration_s,
                 "simulated seconds (default: summary.json's sim_time_s)");
  app.add_option("--seed", options.seed, "ns-3 run number (RngRun)")->capture_default_str();
  app.add_option("--exponent", options.exponent, "log-distance path-loss exponent")
      ->capture_default_str();
  app.add_option("--reference-loss-db", options.reference_loss_db, "loss at the reference distance")
      ->capture_default_str();
  app.add_option("--reference-distance-m", options.reference_distance_m, "reference distance")
      ->capture_default_str();
  app.add_option("--tx-power-dbm", options.tx_power_dbm, "transmit power")->capture_default_str();
  app.add_option("--rx-sensitivity-dbm", options.rx_sensitivity_dbm, "YansWifiPhy RxSensitivity")
      ->capture_default_str();
  app.add_option("--cca-ed-threshold-dbm", options.cca_ed_threshold_dbm,
                 "YansWifiPhy CcaEdThreshold")
      ->capture_default_str();
  app.add_option("--preamble-min-rssi-dbm", options.preamble_min_rssi_dbm,
                 "ThresholdPreambleDetectionModel MinimumRssi: weaker frames are not detected")
      ->capture_default_str();
  app.add_option("--preamble-threshold-db", options.preamble_threshold_db,
                 "ThresholdPreambleDetectionModel Threshold (SNR)")
      ->capture_default_str();
  app.add_option("--noise-figure-db", options.noise_figure_db, "YansWifiPhy RxNoiseFigure")
      ->capture_default_str();
  app.add_option("--error-model", options.error_model, "frame error-rate model")
      ->check(CLI::IsMember({"table", "nist", "yans"}))
      ->capture_default_str();
  app.add_option("--rts-threshold-bytes", options.rts_threshold_bytes,
                 "RTS/CTS above this MPDU size")
      ->capture_default_str();
  app.add_option("--queue-packets", options.queue_packets,
                 "WifiMacQueue MaxSize in packets (0: ns-3's default, 500)");
  app.add_option("--queue-max-delay-s", options.queue_max_delay_s,
                 "WifiMacQueue MaxDelay (0: ns-3's default, 0.5 s)");
  app.add_option("--queue-disc", options.queue_disc,
                 "queue discipline above the MAC. fq_codel: what Ipv4AddressHelper installs, "
                 "with flow control, so the MAC queue stops taking packets when full and they "
                 "wait above it (ns-3 as users run it); none: the MAC queue is the only queue, as "
                 "in SwarmNet and the ns-3 engine")
      ->check(CLI::IsMember({"fq_codel", "none"}))
      ->capture_default_str();
  CLI::Option* arp_entries =
      app.add_option("--arp-entries", options.arp_entries,
                     "ARP entries filled in advance. none: no entry filled, ARP resolves by "
                     "request and reply and ns-3's AODV takes the MAC's dropped MPDUs as "
                     "layer-2 feedback (ns-3's default stack, as users run it); auto-generated: "
                     "every neighbour filled by NeighborCacheHelper, no ARP frame, and no "
                     "layer-2 feedback for AODV (the aligned setup, = --aligned); permanent: "
                     "filled, no ARP frame, AODV with layer-2 feedback")
          ->check(CLI::IsMember({"permanent", "auto-generated", "none"}))
          ->capture_default_str();
  app.add_flag("--aligned", options.aligned,
               "the configuration aligned with SwarmNet's own engine before issue 19 "
               "(docs/validation.md): ARP caches filled in advance (--arp-entries "
               "auto-generated), so no ARP frame and no layer-2 feedback for ns-3's AODV; pair "
               "it with SwarmNet's network.arp: static and aodv link_layer_feedback: false")
      ->excludes(arp_entries);
  app.add_option("--flooding-ttl", options.flooding.ttl, "flooding: hops a packet may travel")
      ->check(CLI::Range(1, 255))
      ->capture_default_str();
  app.add_option("--flooding-jitter-max-s", options.flooding.jitter_max_s,
                 "flooding: largest random delay before a rebroadcast")
      ->capture_default_str();
  app.add_option("--flooding-cache-size", options.flooding.cache_size,
                 "flooding: (originator, sequence) pairs remembered")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if (options.aligned) options.arp_entries = "auto-generated";

  try {
    const nlohmann::ordered_json result = run(options);
    if (options.output.empty()) {
      std::cout << result.dump(2) << '\n';
    } else {
      const std::string temporary = options.output + ".tmp";
      {
        std::ofstream out(temporary);
        out << result.dump(2) << '\n';
        if (!out) throw std::runtime_error(temporary + ": cannot write");
      }
      if (std::rename(temporary.c_str(), options.output.c_str()) != 0) {
        throw std::runtime_error(options.output + ": cannot rename the result into place");
      }
    }
  } catch (const std::exception& error) {
    std::cerr << "swarmnet_ns3_replay: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
