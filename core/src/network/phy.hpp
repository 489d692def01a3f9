// A node's PHY: its transmit/receive state and the decision whether an arriving frame is decoded.
//
// This version is a *threshold PHY*: a frame is received if and only if its received power is at
// least rx_sensitivity_dbm. Frames that overlap in time do not interfere with each other, and a
// node also receives while it transmits (no half-duplex loss). Signals below the sensitivity are
// ignored entirely (they neither raise the carrier sense nor interfere). SINR-based reception
// with interference, noise, capture and half-duplex loss replaces decide() in a later issue; the
// state machine, the arrival list and the listener interface below are the slots it fills.
//
// Carrier sense: medium_busy() is true while the node transmits or while at least one frame above
// the sensitivity is arriving. The listener's medium_busy/medium_idle callbacks report the
// transitions of medium_busy() caused by arriving signals; the start and end of the node's own
// transmission are reported by transmit() itself and by transmit_end() instead (a MAC that
// finishes a transmission while a frame is still arriving asks medium_busy()).
#pragma once

#include <cstdint>
#include <vector>

#include "scenario/scenario.hpp"
#include "swarmnet/mac.hpp"
#include "swarmnet/packet.hpp"

namespace swarmnet {

// What the PHY tells the layer above (the node, which forwards to its MAC).
class PhyListener {
 public:
  virtual void phy_transmit_end() = 0;
  virtual void phy_receive(const Frame& frame, const RxInfo& info) = 0;
  virtual void phy_receive_error() = 0;
  virtual void phy_medium_busy() = 0;
  virtual void phy_medium_idle() = 0;

 protected:
  ~PhyListener() = default;
};

// The weakest signal a PHY with `config` takes any notice of. The channel's cutoff distance is
// computed against it, so that skipping nodes beyond the cutoff changes nothing. Threshold PHY:
// the sensitivity. (With SINR reception, signals below the sensitivity still interfere and this
// becomes an interference floor below the noise.)
double audibility_threshold_dbm(const PhyConfig& config);

class Phy {
 public:
  enum class State : std::uint8_t { idle, transmitting, receiving };

  Phy(const PhyConfig& config, PhyListener& listener);

  [[nodiscard]] State state() const;
  [[nodiscard]] bool medium_busy() const { return transmitting_ || !arrivals_.empty(); }

  // Whether a signal of this power concerns this PHY at all; the channel schedules nothing for
  // signals that do not.
  [[nodiscard]] bool audible(double rx_power_dbm) const;

  // The node's own transmission. start_transmission() while transmitting is a MAC bug and throws
  // std::logic_error.
  void start_transmission();
  void end_transmission();

  // A signal's first and last bit reach this node.
  void signal_start(std::uint64_t frame_uid, double rx_power_dbm);
  void signal_end(const Frame& frame, double rx_power_dbm);

 private:
  struct Arrival {
    std::uint64_t frame_uid;
    double rx_power_dbm;
  };
  // The reception decision for a frame whose signal just ended.
  [[nodiscard]] bool decide(const Arrival& arrival) const;

  PhyConfig config_;
  PhyListener& listener_;
  bool transmitting_ = false;
  std::vector<Arrival> arrivals_;  // signals currently arriving, in arrival order
};

const char* to_string(Phy::State state);

}  // namespace swarmnet
