// The application layer of every node: takes the robots' messages into the network and records
// what reaches each robot.
//
// Injection: a message becomes a Packet (uid from the run-wide counter, message id, source,
// destination, payload shared, sent_at = injection time) handed to the source node's routing.
// A message addressed to its own source is delivered at once with 0 hops.
//
// Delivery: when routing delivers a packet at node n, the robot n gets a Delivery. The first
// delivery of a unicast message at its destination counts towards pdr, delay and hops. Copies of
// a message that node n has already delivered are suppressed (counted as duplicates, not traced,
// not passed to the robot): each node remembers the (sent_at, message id) of what it delivered,
// and forgets an entry once the message is older than kDuplicateWindow. A copy arriving later
// than that after it was sent would be delivered again; no routing protocol here keeps a packet
// that long (flooding lives for ttl jitters, route-request buffers time out within seconds).
#pragma once

#include <cstdint>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "network/network_metrics.hpp"
#include "network/packet_trace.hpp"
#include "network/packet_uid_source.hpp"
#include "network/send_reports.hpp"
#include "protocol/step_data.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/routing.hpp"

namespace swarmnet {

class ApplicationLayer {
 public:
  static constexpr SimTime kDuplicateWindow{std::int64_t{60'000'000'000}};  // 60 s

  // A message waiting for its injection time.
  struct Message {
    std::uint64_t message_id = 0;
    NodeId source = kNoNode;
    NodeId destination = kBroadcast;
    std::uint16_t port = 0;
    std::shared_ptr<const Payload> payload;
    std::uint8_t hop_limit = 0;  // SendOptions::hop_limit
    bool report = false;         // SendOptions::report
  };

  ApplicationLayer(std::size_t node_count, NetworkMetrics& metrics, PacketTraceWriter& trace,
                   PacketUidSource& uids, SendReports& reports);

  // Where deliveries are appended (the current step's result); null: recorded in metrics only.
  void set_output(std::vector<Delivery>* deliveries) { output_ = deliveries; }

  // Takes `message` in at `now`: traces "send", then hands the packet to `source_routing` (the
  // source node's routing), or delivers it at once if it is addressed to its source (its report,
  // if it wants one: sent, to itself, at once).
  void inject(const Message& message, SimTime now, Routing& source_routing);

  // Routing at `receiver` delivers `packet` to its robot at `now`. Returns false for a suppressed
  // duplicate (or a control packet, which carries no message).
  bool deliver(NodeId receiver, const Packet& packet, SimTime now);

  // Unicast messages taken in and not (yet) delivered at their destination.
  [[nodiscard]] std::uint64_t undelivered_unicast() const { return awaiting_.size(); }

 private:
  using SeenKey = std::pair<std::int64_t, std::uint64_t>;  // (sent_at ns, message id)

  NetworkMetrics& metrics_;
  PacketTraceWriter& trace_;
  PacketUidSource& uids_;
  SendReports& reports_;
  std::vector<Delivery>* output_ = nullptr;
  std::vector<std::set<SeenKey>> seen_;  // per node, ordered by sent_at for pruning
  std::set<std::uint64_t> awaiting_;     // unicast message ids not yet at their destination
};

}  // namespace swarmnet
