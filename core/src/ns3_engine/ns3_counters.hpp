// What the ns-3 network did, counted from its trace sources into the Report's counters.
//
// "Data" is a packet carrying a robot message (MessageTag); everything else is ns-3's own (ARP,
// routing control). Every sink is connected per object (no Config path matching), and only
// increments integers, so the counts are exact and the same from run to run.
#pragma once

#include <ns3/ipv4-header.h>
#include <ns3/ipv4-l3-protocol.h>
#include <ns3/node.h>
#include <ns3/packet.h>
#include <ns3/wifi-mac.h>
#include <ns3/wifi-mpdu.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-phy-common.h>

#include <cstdint>

#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet::ns3engine {

struct Counts {
  // MAC and PHY: frames as they go on the air (PhyTxBegin), ARP messages as the MAC takes them.
  std::uint64_t tx_frames = 0;
  std::uint64_t tx_bytes = 0;  // MPDU sizes, MAC header and FCS included
  std::uint64_t data_frames = 0;
  std::uint64_t ack_frames = 0;
  std::uint64_t rts = 0;
  std::uint64_t cts = 0;
  std::uint64_t retries = 0;     // data frames with the Retry bit
  std::uint64_t collisions = 0;  // receptions that failed to decode (RxError)
  std::uint64_t rx_drops = 0;    // receptions the PHY dropped (PhyRxDrop, any reason)
  std::uint64_t arp_requests = 0;
  std::uint64_t arp_replies = 0;
  std::uint64_t arp_drops = 0;       // ArpL3Protocol and ArpCache Drop traces
  std::uint64_t arp_queue_full = 0;  // data among them: ArpL3Protocol's (queue full, dead entry)
  std::uint64_t arp_unresolved = 0;  // data among them: ArpCache's (retries exhausted)
  // Routing.
  std::uint64_t control_packets = 0;  // routing protocol's packets sent on a wireless interface
  std::uint64_t control_bytes = 0;    // their IP sizes
  std::uint64_t data_forwards = 0;    // IP forwards of data; flooding: relays
  std::uint64_t rreq = 0;
  std::uint64_t rrep = 0;
  std::uint64_t hello = 0;
  std::uint64_t rerr = 0;
  std::uint64_t rrep_ack = 0;
  std::uint64_t duplicates = 0;            // flooding: copies already seen
  std::uint64_t flooding_ttl_expired = 0;  // flooding: copies not relayed, ttl spent
  // Data dropped, by reason.
  std::uint64_t no_route = 0;
  std::uint64_t queue_full = 0;
  std::uint64_t ttl_expired = 0;
  std::uint64_t retry_limit = 0;
  std::uint64_t buffer_timeout = 0;
};

class CounterSinks {
 public:
  explicit CounterSinks(Routing routing);
  CounterSinks(const CounterSinks&) = delete;
  CounterSinks& operator=(const CounterSinks&) = delete;
  CounterSinks(CounterSinks&&) = delete;
  CounterSinks& operator=(CounterSinks&&) = delete;
  ~CounterSinks() = default;

  // Connects the sinks to `device` and to `node`'s IPv4 and ARP layers (after its addresses are
  // assigned: each interface's ARP cache exists from then on). `node_id` is the engine's id of
  // the node. The sinks hold `this`.
  void connect(const ns3::Ptr<ns3::Node>& node, std::uint32_t node_id,
               const ns3::Ptr<ns3::WifiNetDevice>& device);

  // For what the endpoints count themselves (flooding relays, sends refused for lack of a route).
  Counts& counts() { return counts_; }
  [[nodiscard]] const Counts& counts() const { return counts_; }

  // Counts a data packet the MAC took but could not queue (call once the events have run).
  void settle();

  [[nodiscard]] Report report(std::uint64_t events) const;

 private:
  void on_phy_tx_begin(ns3::Ptr<const ns3::Packet> packet, double power_w);
  void on_rx_error(ns3::Ptr<const ns3::Packet> packet, double snr);
  void on_phy_rx_drop(ns3::Ptr<const ns3::Packet> packet, ns3::WifiPhyRxfailureReason reason);
  void on_mac_tx(ns3::Ptr<const ns3::Packet> packet);
  void on_queue_enqueue(ns3::Ptr<const ns3::WifiMpdu> mpdu);
  void on_tc_drop(ns3::Ptr<const ns3::Packet> packet);
  void on_dropped_mpdu(ns3::WifiMacDropReason reason, ns3::Ptr<const ns3::WifiMpdu> mpdu);
  void on_arp_queue_drop(ns3::Ptr<const ns3::Packet> packet);  // pending queue full, dead
  void on_arp_give_up(ns3::Ptr<const ns3::Packet> packet);     // resolution gave up
  void on_ip_tx(ns3::Ptr<const ns3::Packet> packet, ns3::Ptr<ns3::Ipv4> ipv4,
                std::uint32_t interface);
  void on_ip_drop(const ns3::Ipv4Header& header, ns3::Ptr<const ns3::Packet> payload,
                  ns3::Ipv4L3Protocol::DropReason reason, ns3::Ptr<ns3::Ipv4> ipv4,
                  std::uint32_t interface);
  static void on_unicast_forward(CounterSinks* sinks, std::uint32_t node_id,
                                 const ns3::Ipv4Header& header, ns3::Ptr<const ns3::Packet> payload,
                                 std::uint32_t interface);
  void count_aodv(const ns3::Ipv4Header& ip, ns3::Ptr<ns3::Packet> udp_payload);

  Routing routing_;
  std::uint16_t control_port_ = 0;  // the routing protocol's UDP port; 0: none
  Counts counts_;
  // A data packet went to the MAC (MacTx) and its queue has not taken it yet. ns-3.37's
  // WifiMacQueue refuses a packet when full without any trace (the FCFS scheduler's drop of the
  // newest returns early), so a refusal shows only as a MacTx without the queue's Enqueue, which
  // follows it at once when it happens at all.
  bool awaiting_enqueue_ = false;
};

}  // namespace swarmnet::ns3engine
