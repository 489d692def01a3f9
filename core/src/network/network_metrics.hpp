// Counters and samples of the network half, reported in summary.json (DESIGN.md section 6).
//
// Definitions:
//   packets.sent                  application messages taken in (unicast and broadcast)
//   packets.delivered             unicast messages that reached their destination at least once
//   packets.dropped.<reason>      packet copies discarded, by DropReason (data and control)
//   packets.broadcast_sent        broadcast messages among `sent`
//   packets.broadcast_deliveries  (broadcast message, receiving node) deliveries
//   packets.undelivered           unicast messages sent and not delivered to their destination
//                                 by the end of the run: dropped, or still queued or travelling.
//                                 (The kernel cannot tell a copy still travelling from one a
//                                 protocol discarded silently, e.g. duplicate suppression, so no
//                                 "in flight" count is offered.)
//   packets.duplicates            copies of an already delivered message that reached a node's
//                                 application and were not passed to the robot again
//   pdr                           delivered / unicast sent (0 when none was sent)
//   delay_s                       over the first delivery of each unicast message at its
//                                 destination: mean, p50 and p95 (nearest rank); null if none
//   hops_mean                     over the same deliveries; null if none
//   mac.*                         tx_frames and tx_bytes (counted by the kernel on transmit),
//                                 collisions (frames the PHY lost to interference: always 0 with
//                                 the threshold PHY, plus whatever the MAC counts under that name),
//                                 retries, and every counter the MACs reported via count()
//   routing.*                     control_packets and control_bytes (every control packet handed
//                                 to a MAC, originated or relayed), data_forwards (trace_forward()
//                                 of data packets) and every counter routing reported via count()
//   arp.*                         network.arp: ns3 (network/arp.hpp): requests_sent (first requests
//                                 and retries) and replies_sent (frames handed to the MAC),
//                                 resolved (entries that became alive), failed (entries that died
//                                 after the last retry), replies_ignored (replies no request of
//                                 the node waited for), frames_dropped (ARP frames its MAC
//                                 discarded); all 0 with network.arp: static. Packets ARP drops
//                                 are in packets.dropped.arp_queue_full and .arp_unresolved.
//   events                        discrete events run
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/network_report.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class NetworkMetrics {
 public:
  NetworkMetrics();

  void message_sent(bool broadcast);
  void unicast_delivered(SimTime delay, std::uint32_t hops);
  void broadcast_delivered() { ++broadcast_deliveries_; }
  void duplicate_suppressed() { ++duplicates_; }
  void dropped(DropReason reason);

  void frame_transmitted(std::uint32_t bytes);
  void control_packet_sent(std::uint32_t bytes);
  void data_forwarded() { ++data_forwards_; }
  void mac_count(std::string_view counter, std::uint64_t amount);
  void routing_count(std::string_view counter, std::uint64_t amount);
  void arp_count(std::string_view counter, std::uint64_t amount);

  [[nodiscard]] std::uint64_t sent() const { return sent_; }
  [[nodiscard]] std::uint64_t unicast_sent() const { return sent_ - broadcast_sent_; }
  [[nodiscard]] std::uint64_t delivered() const { return delays_ns_.size(); }
  [[nodiscard]] std::uint64_t drops(DropReason reason) const;

  // The report described above; `undelivered` and `events` come from the simulator.
  [[nodiscard]] NetworkReport report(std::uint64_t undelivered, std::uint64_t events) const;

 private:
  using CounterMap = std::map<std::string, std::uint64_t, std::less<>>;
  static void add(CounterMap& counters, std::string_view counter, std::uint64_t amount);

  std::uint64_t sent_ = 0;
  std::uint64_t broadcast_sent_ = 0;
  std::uint64_t broadcast_deliveries_ = 0;
  std::uint64_t duplicates_ = 0;
  std::vector<std::int64_t> delays_ns_;
  std::uint64_t hops_total_ = 0;
  std::map<DropReason, std::uint64_t> drops_;
  std::uint64_t data_forwards_ = 0;
  CounterMap mac_;      // starts with tx_frames, tx_bytes, collisions, retries
  CounterMap routing_;  // starts with control_packets, control_bytes
  CounterMap arp_;
};

}  // namespace swarmnet
