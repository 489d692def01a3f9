// Each node's table of the nodes its PHY decoded frames from (network.neighbors), which the
// network half returns with every step's result for RobotContext::neighbors(). Only what the
// robot's own radio could know: a decoded frame's transmitter (data and RTS frames carry one;
// ACK and CTS name only their receiver on the air, so they are not counted), its received power
// and the SINR the PHY judged it at; and, from the MAC, how its unicast exchanges with each
// neighbour ended (acknowledged at the first attempt, later, or given up).
#pragma once

#include <cstdint>
#include <vector>

#include "network/network_settings.hpp"
#include "swarmnet/mac.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/radio_neighbor.hpp"

namespace swarmnet {

class NeighborTables {
 public:
  NeighborTables(std::uint32_t nodes, const NeighborSensing& settings);

  // `receiver`'s PHY decoded `frame` at `now` (the frame's end) with `info`.
  void heard(NodeId receiver, const Frame& frame, const RxInfo& info, SimTime now);
  // `sender`'s MAC ended a unicast exchange with `next_hop` at `now`: acknowledged after
  // `attempts` transmissions, or given up (`acknowledged` false).
  void exchange_ended(NodeId sender, NodeId next_hop, bool acknowledged, std::uint32_t attempts,
                      SimTime now);

  // The tables at `now` (a window's end): `counts[i]` entries for node i, then node i's entries
  // in `entries`, ascending by id. A node heard last at or before now - window_s has left its
  // table; a table holds the max_per_robot most recently heard (ties: the lower id).
  void collect(SimTime now, std::vector<std::uint32_t>& counts,
               std::vector<RadioNeighbor>& entries);

 private:
  // Ages `node`'s exchanges out of the window and counts those left into its heard entries.
  void count_exchanges(std::size_t node, SimTime cutoff);

  struct Heard {
    RadioNeighbor reading;
    std::vector<SimTime> frame_ends;  // of the frames still inside the window, oldest first
  };
  // A node's unicast exchanges with one neighbour, kept apart from Heard: a neighbour that
  // only acknowledges (its ACKs name no transmitter) is not in the table until it is heard.
  struct Exchange {
    SimTime ended{};
    bool first_attempt_ack = false;
  };
  struct Link {
    NodeId neighbor = kNoNode;
    std::vector<Exchange> exchanges;  // still inside the window, oldest first
  };

  SimTime window_;
  std::uint32_t max_per_robot_;
  double smoothing_;
  std::vector<std::vector<Heard>> tables_;  // per receiver, ascending by transmitter id
  std::vector<std::vector<Link>> links_;    // per sender, ascending by neighbour id
  std::vector<std::uint32_t> kept_;         // collect()'s scratch: indices of a table's kept
};

}  // namespace swarmnet
