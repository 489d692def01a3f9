// One network node: its PHY and its MAC and routing plugin instances, and the contexts through
// which those plugins reach the kernel (MacContext, RoutingContext).
//
// The kernel's part of the layer boundaries:
//   routing.send_to_mac()   -> mac.enqueue()          (control packets counted here)
//   mac.transmit()          -> channel                (mac.tx_frames / tx_bytes counted here)
//   phy reception           -> mac.on_receive()
//   mac.deliver()           -> packet.hops + 1, then routing.receive()
//   routing.deliver()       -> application layer
//   drop() from either      -> packet trace "drop" and packets.dropped.<reason>
//   count() from either     -> mac.<counter> or routing.<counter> in the report
#pragma once

#include <cstddef>
#include <string_view>

#include "network/application_layer.hpp"
#include "network/channel.hpp"
#include "network/network_metrics.hpp"
#include "network/packet_trace.hpp"
#include "network/packet_uid_source.hpp"
#include "network/phy.hpp"
#include "network/scheduler.hpp"
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
  NetworkMetrics& metrics;
  PacketUidSource& packet_uids;
  std::uint64_t phy_seed = 0;  // node i's PHY draws from derive_seed(phy_seed, {i})
};

class Node final : private PhyListener {
 public:
  Node(NodeId id, const NodeServices& services, const PhyConfig& phy_config,
       PluginInstance<Mac> mac, PluginInstance<Routing> routing);
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
  class MacPort final : public MacContext {
   public:
    explicit MacPort(Node& node) : node_(node) {}
    [[nodiscard]] NodeId node() const override { return node_.id_; }
    [[nodiscard]] std::size_t node_count() const override;
    [[nodiscard]] SimTime now() const override;
    [[nodiscard]] Vec2 position() const override;
    TimerId schedule(SimTime delay, std::function<void()> callback) override;
    void cancel(TimerId timer) override;
    void count(std::string_view counter, std::uint64_t amount) override;
    void transmit(Frame frame, SimTime duration) override;
    [[nodiscard]] bool medium_busy() const override;
    void deliver(Packet packet, NodeId from) override;
    void link_failed(const Packet& packet, NodeId next_hop) override;
    void drop(const Packet& packet, DropReason reason) override;

   private:
    Node& node_;
  };

  class RoutingPort final : public RoutingContext {
   public:
    explicit RoutingPort(Node& node) : node_(node) {}
    [[nodiscard]] NodeId node() const override { return node_.id_; }
    [[nodiscard]] std::size_t node_count() const override;
    [[nodiscard]] SimTime now() const override;
    [[nodiscard]] Vec2 position() const override;
    TimerId schedule(SimTime delay, std::function<void()> callback) override;
    void cancel(TimerId timer) override;
    void count(std::string_view counter, std::uint64_t amount) override;
    Packet make_control_packet(NodeId destination) override;
    void send_to_mac(Packet packet, NodeId next_hop) override;
    void deliver(const Packet& packet) override;
    void drop(const Packet& packet, DropReason reason) override;
    void trace_forward(const Packet& packet) override;

   private:
    Node& node_;
  };

  void drop(const Packet& packet, DropReason reason);

  // PhyListener: the PHY's events go to the MAC.
  void phy_transmit_end() override { mac_->on_transmit_end(); }
  void phy_receive(const Frame& frame, const RxInfo& info) override {
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
  // Declared last: destroyed first, while the ports they may still call are alive.
  PluginInstance<Mac> mac_;
  PluginInstance<Routing> routing_;
};

}  // namespace swarmnet
