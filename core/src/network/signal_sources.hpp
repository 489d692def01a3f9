// The signals a sinr PHY is not handed as events, and where it finds them (the channel): quiet
// signals (opt-in, network.phy.sensing_floor_db) and far signals (network.channel.far_signals;
// network/phy.hpp, network/far_signals.hpp).
#pragma once

#include <vector>

#include "network/scheduler.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

// A signal too weak to be sensed, as it reaches one receiver.
struct QuietSignal {
  SimTime start;
  SimTime end;
  double power_mw;
};

// A far signal (is_far_signal) as it reaches one receiver: its power, and the keys the channel
// reserved for its first and last bit when the frame was sent.
struct FarSignal {
  std::uint64_t frame_uid = 0;
  double power_dbm = 0.0;
  double power_mw = 0.0;
  EventKey start;
  EventKey end;
};

// Where a sinr PHY learns of the far signals it was not handed as events (the channel), and
// tells when it needs them all as events.
class FarSignalSource {
 public:
  // far_starts answers for start keys at most this long before now.
  static constexpr SimTime kFarStartHistory{1'000'000};

  // Appends to `out`, by start key, the far signals reaching `receiver` that it was not handed as
  // events and whose start key lies strictly between `from` and `to`.
  virtual void far_starts(NodeId receiver, EventKey from, EventKey to,
                          std::vector<FarSignal>& out) const = 0;
  // Appends to `out` (in no order) the far signals reaching `receiver` that it was not handed as
  // events and that arrive during (from, to): start before `to`, end after `from`. Answers for
  // `from` no earlier than kFarStartHistory before now, or than the start of the reception
  // under way; signals that ended before the receiver last got far signals as events are not
  // listed (nothing later depends on them).
  virtual void far_signals_during(NodeId receiver, EventKey from, EventKey to,
                                  std::vector<FarSignal>& out) const = 0;
  // While held, `receiver` gets every far signal as events, as a hot receiver does: the PHY
  // needs to see the next signal start (network.phy.header_failure_cca: ns3, while its MAC counts
  // the medium idle). The far signals still to end are handed over when the hold begins.
  virtual void hold_far_events(NodeId receiver, bool hold) = 0;

 protected:
  ~FarSignalSource() = default;
};

// Where a sinr PHY finds the quiet signals reaching it (the channel).
class QuietSignalSource {
 public:
  // Appends to `out` the quiet signals that reach `receiver` and overlap [from, to).
  virtual void quiet_signals(NodeId receiver, SimTime from, SimTime to,
                             std::vector<QuietSignal>& out) const = 0;

 protected:
  ~QuietSignalSource() = default;
};

}  // namespace swarmnet
