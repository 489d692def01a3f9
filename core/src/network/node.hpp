// One network node: its PHY and its MAC and routing plugin instances, and the contexts through
// which those plugins reach the kernel (MacContext, RoutingContext).
//
// The kernel's part of the layer boundaries:
//   routing.send_to_mac()   -> mac.enqueue()          (control packets counted here)
//   mac.transmit()          -> channel                (mac.tx_frames / tx_bytes counted, and
//                                                      the frame trace written, here)
//   phy reception           -> mac.on_receive()
//   routing.send_to_mac()   -> ARP (network.arp: ns3) for a unicast next hop, then mac.enqueue()
//   mac.deliver()           -> ARP packets to ARP; others: packet.hops + 1, then routing.receive()
//   routing.deliver()       -> application layer
//   drop() from either      -> packet trace "drop" and packets.dropped.<reason>; the sender's
//                              send report if the node is the message's source
//   mac.acknowledged()      -> the sender's send report (acknowledged), and with mac.gave_up()
//                              the neighbour tables' unicast exchanges (network.neighbors)
//   mac.transmit() of a source's own broadcast (or unicast, under a MAC that acknowledges
//                              nothing) -> the sender's send report (sent)
//   count() from either     -> mac.<counter> or routing.<counter> in the report
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string_view>
#include <utility>

#include "network/application_layer.hpp"
#include "network/arp.hpp"
#include "network/channel.hpp"
#include "network/frame_trace.hpp"
#include "network/neighbor_tables.hpp"
#include "network/network_metrics.hpp"
#include "network/packet_trace.hpp"
#include "network/packet_uid_source.hpp"
#include "network/phy.hpp"
#include "network/scheduler.hpp"
#include "network/send_reports.hpp"
#include "plugin/plugin_instance.hpp"
#include "swarmnet/mac.hpp"
#include "swarmnet/routing.hpp"

namespace swarmnet {

// The kernel services a node uses; all outlive the node.
struct NodeServices {
  Scheduler& scheduler;
  Channel& channel;
  ApplicationLayer& application;
  PacketTraceWriter& trace;
  FrameTraceWriter& frames;
  NetworkMetrics& metrics;
  PacketUidSource& packet_uids;
  SendReports& send_reports;            // told of this node's own messages' outcomes
  std::uint64_t phy_seed = 0;           // node i's PHY draws from derive_seed(phy_seed, {i})
  std::uint64_t arp_seed = 0;           // node i's ARP jitter draws from derive_seed(arp_seed, {i})
  NeighborTables* neighbors = nullptr;  // network.neighbors: told of every decoded frame
};

class Node final : private PhyListener {
 public:
  // `arp`: ARP's timings, or nullopt for static entries (every address known, no ARP frame).
  Node(NodeId id, const NodeServices& services, const PhyConfig& phy_config,
       const std::optional<ArpTimings>& arp, PluginInstance<Mac> mac,
       PluginInstance<Routing> routing);
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  Node(Node&&) = delete;
  Node& operator=(Node&&) = delete;
  ~Node() = default;

  // Calls attach() on the MAC, then on routing.
  void attach();

  [[nodiscard]] NodeId id() const { return id_; }
  [[nodiscard]] Phy& phy() { return phy_; }
  [[nodiscard]] const Phy& phy() const { return phy_; }
  [[nodiscard]] Mac& mac() { return *mac_; }
  [[nodiscard]] Routing& routing() { return *routing_; }

 private:
  // What both ports give their plugin alike: the node's identity, the clock and timers.
  template <typename Context>
  class Port : public Context {
   public:
    explicit Port(Node& node) : node_(node) {}
    [[nodiscard]] NodeId node() const final { return node_.id_; }
    [[nodiscard]] std::size_t node_count() const final {
      return node_.services_.channel.node_count();
    }
    [[nodiscard]] SimTime now() const final { return node_.services_.scheduler.now(); }
    [[nodiscard]] Vec2 position() const final {
      return node_.services_.channel.position(node_.id_);
    }
    TimerId schedule(SimTime delay, std::function<void()> callback) final {
      return node_.services_.scheduler.schedule_in(delay, std::move(callback));
    }
    void cancel(TimerId timer) final { node_.services_.scheduler.cancel(timer); }

   protected:
    Node& node_;
  };

  class MacPort final : public Port<MacContext> {
   public:
    using Port::Port;
    void count(std::string_view counter, std::uint64_t amount) override;
    void transmit(Frame frame, SimTime duration) override;
    [[nodiscard]] bool medium_busy() const override;
    void deliver(Packet packet, NodeId from) override;
    void link_failed(const Packet& packet, NodeId next_hop) override;
    void drop(const Packet& packet, DropReason reason) override;
    void acknowledged(const Packet& packet, NodeId next_hop, std::uint32_t attempts) override;
    void gave_up(const Packet& packet, NodeId next_hop, std::uint32_t attempts) override;
  };

  class RoutingPort final : public Port<RoutingContext> {
   public:
    using Port::Port;
    void count(std::string_view counter, std::uint64_t amount) override;
    Packet make_control_packet(NodeId destination) override;
    void send_to_mac(Packet packet, NodeId next_hop) override;
    void deliver(const Packet& packet) override;
    void drop(const Packet& packet, DropReason reason) override;
    void trace_forward(const Packet& packet) override;
    [[nodiscard]] bool link_address_known(NodeId neighbor) const override;
  };

  // ARP's way down to the MAC and to the node's drop accounting.
  class ArpLink final : public Arp::Link {
   public:
    explicit ArpLink(Node& node) : node_(node) {}
    Packet make_packet(NodeId destination) override { return node_.new_packet(destination); }
    void send_to_mac(Packet packet, NodeId next_hop) override;
    void drop(const Packet& packet, DropReason reason) override { node_.drop(packet, reason); }

   private:
    Node& node_;
  };

  void drop(const Packet& packet, DropReason reason);
  // A packet of this node's own (routing's control packets, ARP's): fresh uid, no message.
  Packet new_packet(NodeId destination);

  // PhyListener: the PHY's events go to the MAC.
  void phy_transmit_end() override { mac_->on_transmit_end(); }
  void phy_receive(const Frame& frame, const RxInfo& info) override {
    if (services_.neighbors != nullptr) {
      services_.neighbors->heard(id_, frame, info, services_.scheduler.now());
    }
    mac_->on_receive(frame, info);
  }
  void phy_receive_error() override { mac_->on_receive_error(); }
  void phy_medium_busy() override { mac_->on_medium_busy(); }
  void phy_medium_idle() override { mac_->on_medium_idle(); }
  void phy_collision(const Frame& frame) override;

  NodeId id_;
  NodeServices services_;
  Phy phy_;
  MacPort mac_port_;
  RoutingPort routing_port_;
  ArpLink arp_link_;
  std::optional<Arp> arp_;  // empty with static ARP
  // Declared last: destroyed first, while the ports they may still call are alive.
  PluginInstance<Mac> mac_;
  PluginInstance<Routing> routing_;
};

}  // namespace swarmnet
