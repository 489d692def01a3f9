// `ideal_mac`: a contention-free MAC. Packets wait in a FIFO interface queue and leave one frame
// at a time, each taking its serialisation delay on the air; there is no carrier sense, backoff,
// acknowledgement or retry.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <utility>

#include "swarmnet/mac.hpp"

namespace swarmnet::ideal_mac {

class IdealMac final : public Mac {
 public:
  static PluginInfo info();
  explicit IdealMac(const PluginArgs& args);

  void attach(MacContext& context) override { context_ = &context; }
  void enqueue(Packet packet, NodeId next_hop) override;
  void on_transmit_end() override;
  void on_receive(const Frame& frame, const RxInfo& info) override;

  // Time on the air of a frame carrying `packet_bytes` above the MAC.
  [[nodiscard]] SimTime airtime(std::uint32_t packet_bytes) const;

 private:
  void start(Packet packet, NodeId next_hop);

  MacContext* context_ = nullptr;
  double bitrate_bps_;
  std::uint32_t header_bytes_;
  std::size_t queue_limit_;
  std::uint16_t next_sequence_ = 0;  // 802.11-style sequence number, wraps
  bool transmitting_ = false;
  std::deque<std::pair<Packet, NodeId>> queue_;  // waiting packets, not the one on the air
};

}  // namespace swarmnet::ideal_mac
