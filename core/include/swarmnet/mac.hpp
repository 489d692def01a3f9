// MAC plugins: one instance per node, between routing above and the kernel's PHY below.
#pragma once

#include "swarmnet/node_context.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/plugin.hpp"

namespace swarmnet {

// What the PHY measured about a received frame.
struct RxInfo {
  double rx_power_dbm = 0.0;
  double sinr_db = 0.0;
};

class MacContext : public NodeContext {
 public:
  // Puts `frame` on the air now for `duration`; on_transmit_end() follows. The kernel assigns
  // frame.uid and frame.transmitter. A MAC transmits one frame at a time.
  virtual void transmit(Frame frame, SimTime duration) = 0;
  // Clear-channel assessment: true while the PHY senses energy or is transmitting/receiving.
  [[nodiscard]] virtual bool medium_busy() const = 0;

  // Hands a received packet to routing; `from` is the previous hop.
  virtual void deliver(Packet packet, NodeId from) = 0;
  // Tells routing that `next_hop` did not acknowledge `packet` within the retry limit.
  virtual void link_failed(const Packet& packet, NodeId next_hop) = 0;
  // Discards a packet (traced and counted).
  virtual void drop(const Packet& packet, DropReason reason) = 0;
  // Tells the kernel that `next_hop` acknowledged `packet` after `attempts` transmissions (RTS
  // or data; 1 for the first). A MAC whose acknowledges_unicasts() is true calls it for every
  // acknowledged unicast: the sender's send report (swarmnet/send_report.hpp) comes from it.
  virtual void acknowledged(const Packet& packet, NodeId next_hop, std::uint32_t attempts) = 0;
  // Tells the kernel that the MAC gave up `packet` to `next_hop` after `attempts` transmissions
  // without an acknowledgement (its retry limit, or its lifetime ran out mid-exchange); call it
  // before drop() or link_failed(). With acknowledged(), it feeds the radio neighbour tables'
  // share of unicasts acknowledged at the first attempt (swarmnet/radio_neighbor.hpp).
  virtual void gave_up(const Packet& packet, NodeId next_hop, std::uint32_t attempts) = 0;

 protected:
  ~MacContext() = default;
};

class Mac : public Plugin {
 public:
  static constexpr PluginKind kKind = PluginKind::mac;

  // Called once before any traffic; the context outlives the plugin instance.
  virtual void attach(MacContext& context) = 0;
  // Whether this MAC learns that a unicast arrived (an ACK) and says so through
  // MacContext::acknowledged(). If not, a sender's report says its unicast was `sent` when its
  // frame went on the air, as for a broadcast.
  [[nodiscard]] virtual bool acknowledges_unicasts() const { return false; }
  // From routing: send `packet` to `next_hop` (or kBroadcast).
  virtual void enqueue(Packet packet, NodeId next_hop) = 0;
  // The frame given to transmit() has left the antenna.
  virtual void on_transmit_end() = 0;
  // A frame was received without error (addressed to this node or not: the MAC filters).
  virtual void on_receive(const Frame& frame, const RxInfo& info) = 0;
  // A frame was sensed but could not be decoded (for EIFS).
  virtual void on_receive_error() {}
  // Clear-channel assessment changed.
  virtual void on_medium_busy() {}
  virtual void on_medium_idle() {}
};

}  // namespace swarmnet
