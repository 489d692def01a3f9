// The send reports a network half owes (SendOptions::report): which messages want one, and the
// first outcome each meets at its own source node (swarmnet/send_report.hpp). Nodes tell it of
// their own messages' drops, acknowledgements and transmissions; the window's reports leave with
// the step's result.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "protocol/step_data.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/send_report.hpp"

namespace swarmnet {

class SendReports {
 public:
  // Message `message_id` from robot `source`'s controller at `port` wants its report.
  void expect(std::uint64_t message_id, NodeId source, std::uint16_t port);

  // Whether any message awaits its report: while none does, nodes need not look.
  [[nodiscard]] bool awaiting() const { return !awaiting_.empty(); }

  // `node`'s stack met `outcome` with `packet` at `now`. Reported only for the node's own
  // message awaiting its report, and only the first time; `reason` counts for `dropped` only.
  void met(NodeId node, const Packet& packet, SendOutcome outcome, SimTime now,
           NodeId next_hop = kNoNode, std::uint32_t attempts = 0,
           DropReason reason = DropReason::no_route);

  // Moves the reports made since the last call to the end of `out`, in the order they were met.
  void collect(std::vector<AddressedSendReport>& out);

 private:
  struct Sender {
    NodeId source;
    std::uint16_t port;
  };
  std::map<std::uint64_t, Sender> awaiting_;  // by message id
  std::vector<AddressedSendReport> ready_;
};

}  // namespace swarmnet
