// The wireless channel: fans a transmission out to the nodes that can hear it.
//
// For each candidate receiver (the transmitter excluded) it computes the received power through
// the propagation chain, starting at the PHY's tx power plus the transmit antenna gain, then adds
// the receive antenna gain, and, if the signal reaches the PHY's event threshold
// (event_threshold_dbm), hands it the signal's start at now + distance / c and its end one frame
// duration later, in arrival order
// (receivers at equal distance by ascending id). The transmitter's PHY ends its transmission at
// now + duration. Powers and delays are fixed when the frame is sent (positions are constant
// within a step), or at the transmitter's first frame of the step when links are reused (below).
//
// Quiet signals (sinr model, network/phy.hpp): receivers whose signal is below the PHY's event
// threshold get no events. The grid neighbourhood is searched only to the event cutoff (where
// the strongest possible signal falls below that threshold), and the channel keeps the frames
// still on the air, with the positions they were sent from, to answer a PHY's quiet_signals()
// query by computing those links then, exactly as it would have at the transmission.
//
// Far signals (sinr model, network.channel.far_signals: lazy): a receiver whose signal is too weak
// to be detected or sensed alone gets no events from the fan-out; the channel hands the frame to
// FarSignals (network/far_signals.hpp), which hands such signals to a receiver only when they can
// matter there. Their links keep their reserved sequence numbers, so every event runs where it
// would have.
//
// Fan-out: the receivers' signal starts and ends are not put in the scheduler one event each (two
// heap entries per receiver per frame made the heap, not the physics, the network half's main
// cost). A frame's receivers are kept in a FrameFanout sorted by arrival, and one event per
// stream (starts, ends) walks them, each step scheduled with the sequence number reserved for it
// when the frame was sent. Events therefore run in exactly the order per-receiver events would.
//
// Link reuse: positions are fixed within a step, so when no propagation model varies per frame
// (Propagation::varies_per_frame) a transmitter's receivers, delays and powers are computed at its
// first frame of the step and shared by its later ones (a busy node sends several per step).
//
// Candidates: with the cutoff on (settings.network.channel.cutoff) and a finite cutoff distance,
// the nodes of a uniform grid neighbourhood closer than the cutoff; otherwise every node. Both
// give the same frames at the same receivers at the same times, because a node at or beyond the
// cutoff cannot hear the frame whatever the random draws (see cutoff_distance_m), and random
// models draw per (transmitter, receiver, frame uid), not per visit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <vector>

#include "network/channel_links.hpp"
#include "network/far_signals.hpp"
#include "network/network_settings.hpp"
#include "network/phy.hpp"
#include "network/propagation_chain.hpp"
#include "network/radio_thresholds.hpp"
#include "network/scheduler.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/spatial_grid.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

class Channel final : public QuietSignalSource {
 public:
  Channel(const NetworkSettings& settings, PropagationChain chain, Scheduler& scheduler,
          std::size_t node_count);

  Channel(const Channel&) = delete;
  Channel& operator=(const Channel&) = delete;
  Channel(Channel&&) = delete;
  Channel& operator=(Channel&&) = delete;
  ~Channel() = default;

  // Registers node `node`'s PHY (and makes the channel its quiet-signal source); every node must
  // have one before the first transmission, and none is attached after it (std::logic_error).
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
  // The distance from which no node gets a frame as events (its signal is at most quiet):
  // cutoff_distance_m against the PHY's event threshold. The grid is searched to this distance.
  [[nodiscard]] double event_cutoff_m() const { return event_cutoff_m_; }
  // Whether transmissions visit a grid neighbourhood (cutoff on and finite) or every node.
  [[nodiscard]] bool uses_grid() const { return use_grid_; }
  [[nodiscard]] const PropagationChain& propagation() const { return chain_; }
  [[nodiscard]] std::uint64_t frames_sent() const { return next_frame_uid_ - 1; }

  // Propagation delay over `distance_m`, rounded to the nearest nanosecond.
  static SimTime propagation_delay(double distance_m);

  void quiet_signals(NodeId receiver, SimTime from, SimTime to,
                     std::vector<QuietSignal>& out) const override;

 private:
  using Link = ChannelLink;
  // A frame that may still reach someone, for quiet-signal queries.
  struct OnAir {
    std::uint64_t uid;
    NodeId transmitter;
    SimTime sent;
    SimTime duration;
    std::shared_ptr<const std::vector<Vec2>> positions;  // every node's, when it was sent
  };
  struct FrameFanout {
    Frame frame;
    SimTime sent{};
    SimTime duration{};
    std::shared_ptr<const ChannelLinks>
        step_links;                          // the transmitter's links of the step, if reused
    ChannelLinks own_links;                  // this frame's links otherwise (capacity kept)
    const ChannelLinks* link_set = nullptr;  // whichever of the two this frame uses
    std::uint64_t first_sequence = 0;        // link i's signal starts with first_sequence + 2 i
    std::size_t next_start = 0;  // each stream's next place in link_set->near (or its end)
    std::size_t next_end = 0;

    // When and with which reserved sequence number link i's start (kEnds false) or end runs.
    template <bool kEnds>
    [[nodiscard]] SimTime step_time(std::size_t i) const {
      const SimTime delay = link_set->links[i].delay;
      return kEnds ? sent + delay + duration : sent + delay;
    }
    template <bool kEnds>
    [[nodiscard]] std::uint64_t step_sequence(std::size_t i) const {
      return first_sequence + 2 * i + (kEnds ? 1 : 0);
    }
  };

  // Updates the bounds, the grid (if used) and longest_reach_ after the positions changed.
  void rebuild_grid();
  void remember_on_air(const Frame& frame, SimTime duration);
  // The power a link delivers, after the receive antenna; transmit() and quiet_signals() must
  // agree on it to the bit.
  [[nodiscard]] double link_power_dbm(const RadioLink& link) const;
  // Fills `links` with the receivers that get `transmitter`'s frame `uid` as events, in arrival
  // order.
  void compute_links(NodeId transmitter, std::uint64_t uid, ChannelLinks& links) const;
  std::uint32_t acquire_fanout();
  void release_fanout(std::uint32_t fanout);
  // Schedules the next step of one stream of a frame's fan-out: its receivers' signal starts
  // (kEnds false) or ends, in arrival order.
  template <bool kEnds>
  void schedule_next(std::uint32_t fanout);

  PropagationChain chain_;
  Scheduler& scheduler_;
  double tx_power_dbm_;  // transmit power plus transmit antenna gain
  double rx_gain_db_;
  double audibility_dbm_;  // at the receiver, after its antenna gain
  double event_dbm_;       // likewise; equal to audibility_dbm_ when there are no quiet signals
  double cutoff_m_;
  double event_cutoff_m_;
  bool use_grid_;
  bool has_quiet_signals_;
  bool cache_links_;  // the chain gives a link the same power for every frame
  bool far_lazy_;     // far signals go to FarSignals, not to events (network.channel.far_signals)
  FarSignalTest is_far_;
  std::vector<Phy*> phys_;
  // compute_links' scratch.
  mutable FarIndexScratch far_index_scratch_;
  mutable std::vector<std::uint64_t> arrival_keys_;
  mutable std::vector<Link> sorted_links_;
  std::vector<Vec2> positions_;
  std::shared_ptr<const std::vector<Vec2>> positions_snapshot_;  // made at the step's first frame
  std::deque<OnAir> on_air_;                                     // by time sent
  SimTime longest_duration_{};
  SimTime longest_reach_{};  // the largest propagation delay a remembered frame can have
  SpatialGrid grid_;
  Rect arena_bounds_;
  Rect grid_bounds_;
  bool grid_ready_ = false;
  // Per transmitter, its links in the current step (cache_links_ only; emptied by set_positions).
  std::vector<std::shared_ptr<const ChannelLinks>> step_links_;
  std::unique_ptr<FarSignals> far_signals_;  // far_lazy_ only
  // Fan-outs are recycled (by index, so growth does not move a live one's address in use).
  std::vector<std::unique_ptr<FrameFanout>> fanouts_;
  std::vector<std::uint32_t> free_fanouts_;
  std::uint64_t next_frame_uid_ = 1;
};

}  // namespace swarmnet
