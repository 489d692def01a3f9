// Far signals without events (issue 13; the model is in network/phy.hpp, "Far signals").
//
// A frame reaches about 190 receivers inside the interference cutoff of the study's scenario but
// can be detected by about 9: the rest get a far signal, which matters to a receiver only when it
// judges a preamble or receives a frame (interference), when the far signals arriving at it
// could add up to the carrier-sense threshold, and for the detection windows they open. This
// keeps the frames with far links on the air, and per receiver the list of those that reach it
// (the index the PHYs ask: far_starts, far_signals_during; a question visits its receiver's
// frames, not every frame on the air) and an upper bound of the far power still to end there, in
// integer units rounded up (exact sums, no drift). From the frame that takes that bound to the
// threshold until frames retire below it again, and while its PHY holds far signals as events
// (hold_far_events: header_failure_cca ns3), the receiver is "hot" and gets every far signal as
// events; when it becomes hot it is handed those still to end that it was not handed
// (Phy::begin_far_events). The cost of a far link that is not handed over is two integer
// additions and an entry in the receiver's list per frame, instead of two events at its PHY.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "network/channel_links.hpp"
#include "network/phy.hpp"
#include "network/scheduler.hpp"

namespace swarmnet {

class FarSignals final : public FarSignalSource {
 public:
  // `sensing_mw`: the lower of the two carrier-sense thresholds; `phys`: every node's PHY (set
  // before the first frame).
  FarSignals(Scheduler& scheduler, const std::vector<Phy*>& phys, double sensing_mw);

  // A link's power in this bookkeeping's units, rounded up.
  [[nodiscard]] std::int64_t units(double power_mw) const;

  // A frame was sent now with these links (reused links: shared, kept while the frame may still
  // be asked about) and the sequence numbers reserved from `first_sequence` (two per link, in
  // link order). Hands its far signals to the receivers that get them as events.
  void frame_sent(std::uint64_t uid, SimTime duration, std::uint64_t first_sequence,
                  std::shared_ptr<const ChannelLinks> links);

  void far_starts(NodeId receiver, EventKey from, EventKey to,
                  std::vector<FarSignal>& out) const override;
  void far_signals_during(NodeId receiver, EventKey from, EventKey to,
                          std::vector<FarSignal>& out) const override;
  void hold_far_events(NodeId receiver, bool hold) override;

  // How many frames are kept, and how many entries a receiver's list holds (tests).
  [[nodiscard]] std::size_t frames_kept() const { return frames_.size(); }
  [[nodiscard]] std::size_t entries_kept(NodeId receiver) const {
    return receivers_[receiver].frames.size();
  }

 private:
  struct AirFrame {
    std::uint64_t uid;
    SimTime sent;
    SimTime duration;
    SimTime last_end;  // when its last far signal ends
    std::uint64_t first_sequence;
    std::shared_ptr<const ChannelLinks> links;
    std::uint64_t number;  // frames with far links are numbered in the order sent
    bool counted = true;   // its far units are still in the receivers' bounds
  };
  // A kept frame that reaches a receiver with a far link, in that receiver's list: a question
  // visits the frames that reach its receiver, not every frame on the air (at thousands of
  // robots most of those are beyond the receiver's cutoff).
  struct FarEntry {
    std::uint64_t number;  // the frame's
    std::uint32_t link;    // the index of its far link to this receiver
  };
  struct Receiver {
    std::int64_t pending_units = 0;  // far power that has not surely ended, rounded up
    // pending_units reached the threshold, or the PHY holds far signals as events: every far
    // signal goes as events. When it became hot, the far signals it had not been handed that
    // were still to end were handed; the others had ended, and no question asked while hot
    // concerns them.
    bool hot = false;
    // A PHY holds far signals as events (hold_far_events): hot, whatever pending_units says.
    bool held = false;
    // Not hot: the frames numbered from here on were not handed over (every earlier one was, or
    // ended before it last became hot).
    std::uint64_t lazy_from = 0;
    // The frames with a far link here, in the order sent; entries of frames no longer kept are
    // dropped when the list is full (remember_at).
    std::vector<FarEntry> frames;
  };

  [[nodiscard]] static FarSignal signal_of(const AirFrame& frame, std::size_t link);
  // The number of the oldest kept frame (the next frame's when none is kept).
  [[nodiscard]] std::uint64_t oldest_number() const;
  // Adds a frame to a receiver's list, forgetting those numbered below `oldest` if it is full.
  static void remember_at(Receiver& r, std::uint64_t oldest, FarEntry entry);
  // Takes back the units of the frames whose far signals have all ended, and forgets the frames
  // nobody can ask about any more.
  void retire(SimTime now);
  void begin_events(NodeId receiver);
  void end_events(NodeId receiver);
  // Calls f(frame, link index) for each kept frame not handed to `receiver` (none while it is
  // hot) that reaches it with a far signal, was sent at or after `sent_from` and is on the air
  // somewhere at or after `ends_after`, latest first.
  template <typename F>
  void for_each_far_frame(NodeId receiver, SimTime sent_from, SimTime ends_after, F&& f) const;

  Scheduler& scheduler_;
  const std::vector<Phy*>& phys_;
  double units_per_mw_;
  std::int64_t hot_units_;
  std::vector<Receiver> receivers_;
  std::deque<AirFrame> frames_;   // by time sent, numbered consecutively: frames_[i] is number
                                  // oldest_number() + i
  std::size_t counted_from_ = 0;  // frames_[i] for i below it no longer count
  std::uint64_t next_number_ = 0;
  SimTime longest_reach_{};  // the largest propagation delay of a kept frame's links
  SimTime longest_duration_{};
  std::vector<FarSignal> scratch_;
};

}  // namespace swarmnet
