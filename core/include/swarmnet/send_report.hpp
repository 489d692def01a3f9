// How a controller's message may travel (SendOptions), and what its own node's stack can tell it
// of the message's fate (SendReport): what a real robot's radio and IP stack know at the sender,
// no more. End-to-end delivery is not reported: an application acknowledgement is the
// controller's own business (docs/plugins.md, "Send options and send reports").
#pragma once

#include <cstdint>

#include "swarmnet/ids.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

struct SendOptions {
  // Links the message may cross (Packet::hop_limit): 1 reaches this robot's radio neighbours
  // only, and no routing protocol relays it further; 0 leaves it to the routing protocol's own
  // limit (flooding's ttl, AODV's data_ttl).
  std::uint8_t hop_limit = 0;
  // Whether this message's SendReport is wanted (RobotContext::send_reports()).
  bool report = false;
};

enum class SendOutcome : std::uint8_t {
  // A unicast's first hop acknowledged its frame (a MAC that acknowledges unicasts: dcf80211).
  acknowledged,
  // Its frame left this robot's antenna: a broadcast, or a unicast under a MAC that acknowledges
  // nothing (ideal_mac), which cannot know more.
  sent,
  // This robot's own stack discarded it before it left (reason): no route, a full queue, ARP,
  // the hop limit, a route request's buffer timing out, or the MAC's retry limit.
  dropped,
};

inline const char* to_string(SendOutcome outcome) {
  switch (outcome) {
    case SendOutcome::acknowledged:
      return "acknowledged";
    case SendOutcome::sent:
      return "sent";
    case SendOutcome::dropped:
      return "dropped";
  }
  return "?";
}

// One message's fate at its own node: the first of those outcomes, and the only one reported.
struct SendReport {
  std::uint64_t message_id = 0;  // as send() returned it
  SendOutcome outcome = SendOutcome::sent;
  DropReason reason = DropReason::no_route;  // meaningful for `dropped` only
  SimTime at{};                              // when the outcome happened, in network time
  // acknowledged and sent: the frame's receiver (the first hop, or kBroadcast); dropped: kNoNode.
  NodeId next_hop = kNoNode;
  // acknowledged: the MAC's attempts (RTS or data frames) the exchange took, 1 for the first;
  // otherwise 0.
  std::uint32_t attempts = 0;
};

}  // namespace swarmnet
