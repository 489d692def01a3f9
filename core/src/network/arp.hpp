// ARP on one node, as ns-3.37's ArpL3Protocol runs it over 802.11 (network.arp: ns3): routing's
// unicast packets wait for the neighbour's link-layer address, which a broadcast request asks
// for and a unicast reply gives; both travel through the node's MAC like any frame, so they
// contend, collide and are retried. A neighbour that answers none of 1 + max_retries requests
// is dead for dead_timeout, and packets for it are dropped meanwhile. ns-3 never learns an
// address from a request it hears (its bug 107), only from a reply to its own request, and so
// neither does this.
//
// With network.arp: static there is no Arp: every address is known before the run (ns-3's
// NeighborCacheHelper), no ARP frame is sent.
#pragma once

#include <cstdint>

#include "network/arp_cache.hpp"
#include "network/network_metrics.hpp"
#include "network/scheduler.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet {

class Arp {
 public:
  // What ARP needs of its node: new packets, the MAC's queue, and the node's drop accounting.
  class Link {
   public:
    // A fresh packet from this node to `destination` (uid, source, sent_at set; no message).
    virtual Packet make_packet(NodeId destination) = 0;
    virtual void send_to_mac(Packet packet, NodeId next_hop) = 0;
    virtual void drop(const Packet& packet, DropReason reason) = 0;

   protected:
    ~Link() = default;
  };

  Arp(NodeId self, const ArpTimings& timings, Scheduler& scheduler, NetworkMetrics& metrics,
      std::uint64_t seed, Link& link);
  Arp(const Arp&) = delete;
  Arp& operator=(const Arp&) = delete;

  // An IP packet for neighbour `next_hop` (never kBroadcast): sent at once when its address is
  // known, else held for a reply or dropped (arp_queue_full, arp_unresolved).
  void send(Packet packet, NodeId next_hop);
  // An ARP packet the MAC received (a request heard by every neighbour, or a reply to this node).
  void receive(const Packet& packet);
  // Whether `neighbor`'s address is known and fresh now.
  [[nodiscard]] bool resolved(NodeId neighbor) const;

 private:
  void send_request(NodeId neighbor);
  void send_reply(NodeId requester);
  void reply_received(NodeId neighbor);
  void start_timer_if_needed();
  void wait_reply_timeout();
  [[nodiscard]] Packet make_arp_packet(LinkProtocol protocol, NodeId destination);

  NodeId self_;
  ArpCache cache_;
  Scheduler& scheduler_;
  NetworkMetrics& metrics_;
  RandomStream random_;  // request jitter only
  Link& link_;
};

}  // namespace swarmnet
