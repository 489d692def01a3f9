// The wireless channel: fans a transmission out to the nodes that can hear it.
//
// For each candidate receiver (ascending node id, the transmitter excluded) it computes the
// received power through the propagation chain, starting at the PHY's tx power plus the transmit
// antenna gain, then adds the receive antenna gain, and, if the
// receiving PHY finds the signal audible, schedules the signal's start at now + distance / c and
// its end one frame duration later. The transmitter's PHY ends its transmission at now + duration.
// Powers and delays are fixed when the frame is sent (positions are constant within a step).
//
// Candidates: with the cutoff on (scenario.network.channel.cutoff) and a finite cutoff distance,
// the nodes of a uniform grid neighbourhood closer than the cutoff; otherwise every node. Both
// give the same frames at the same receivers at the same times, because a node at or beyond the
// cutoff cannot hear the frame whatever the random draws (see cutoff_distance_m), and random
// models draw per (transmitter, receiver, frame uid), not per visit.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "network/phy.hpp"
#include "network/propagation_chain.hpp"
#include "network/scheduler.hpp"
#include "scenario/scenario.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/spatial_grid.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

class Channel {
 public:
  Channel(const Scenario& scenario, PropagationChain chain, Scheduler& scheduler,
          std::size_t node_count);

  // Registers node `node`'s PHY; every node must have one before the first transmission.
  void attach(NodeId node, Phy& phy);

  // Moves every node (one position per node) and rebuilds the grid.
  void set_positions(std::span<const Vec2> positions);
  [[nodiscard]] const Vec2& position(NodeId node) const { return positions_[node]; }
  [[nodiscard]] std::size_t node_count() const { return positions_.size(); }

  // Puts `frame` on the air from `transmitter` for `duration`; assigns frame.uid and
  // frame.transmitter. Throws std::logic_error if the transmitter is already transmitting.
  void transmit(NodeId transmitter, Frame frame, SimTime duration);

  // The distance from which no node can notice a frame (+infinity if none): cutoff_distance_m
  // against the PHY's audibility threshold.
  [[nodiscard]] double cutoff_m() const { return cutoff_m_; }
  // Whether transmissions visit a grid neighbourhood (cutoff on and finite) or every node.
  [[nodiscard]] bool uses_grid() const { return use_grid_; }
  [[nodiscard]] const PropagationChain& propagation() const { return chain_; }
  [[nodiscard]] std::uint64_t frames_sent() const { return next_frame_uid_ - 1; }

  // Propagation delay over `distance_m`, rounded to the nearest nanosecond.
  static SimTime propagation_delay(double distance_m);

 private:
  void rebuild_grid();

  PropagationChain chain_;
  Scheduler& scheduler_;
  double tx_power_dbm_;  // transmit power plus transmit antenna gain
  double rx_gain_db_;
  double cutoff_m_;
  bool use_grid_;
  std::vector<Phy*> phys_;
  std::vector<Vec2> positions_;
  SpatialGrid grid_;
  Rect arena_bounds_;
  Rect grid_bounds_;
  bool grid_ready_ = false;
  std::vector<NodeId> candidates_;  // scratch, reused by every transmission
  std::uint64_t next_frame_uid_ = 1;
};

}  // namespace swarmnet
