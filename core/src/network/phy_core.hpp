// The state a node's PHY has whatever its reception model: the node's own transmission and the
// carrier-sense state last reported to the layer above. A reception model (threshold_reception,
// sinr_reception; network/phy.hpp describes both) derives from PhyCore and decides what arriving
// signals do: whether a frame is received, and when the medium is busy apart from the node's
// own transmission.
#pragma once

#include <cstdint>

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
  // sinr model: a locked frame was lost to interference (network/phy.hpp); before
  // phy_receive_error.
  virtual void phy_collision(const Frame& /*frame*/) {}

 protected:
  ~PhyListener() = default;
};

class PhyCore {
 public:
  enum class State : std::uint8_t { idle, transmitting, receiving, busy };

  PhyCore(const PhyCore&) = delete;
  PhyCore& operator=(const PhyCore&) = delete;
  PhyCore(PhyCore&&) = delete;
  PhyCore& operator=(PhyCore&&) = delete;
  virtual ~PhyCore() = default;

  [[nodiscard]] State state() const;
  [[nodiscard]] bool medium_busy() const { return transmitting_ || senses_busy(); }

  // The node's own transmission. start_transmission() while transmitting is a MAC bug and throws
  // std::logic_error. The listener hears of neither (the MAC knows), only of the end.
  void start_transmission();
  void end_transmission();

  // A signal's first and last bit reach this node; `start_sequence` is the sequence number of
  // the start's scheduler key (network/phy.hpp).
  virtual void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw,
                            std::uint64_t start_sequence) = 0;
  // The same for a signal whose start has no reserved key (tests): the model takes one if it
  // needs one.
  virtual void signal_start(std::uint64_t frame_uid, double rx_power_dbm, double rx_power_mw) = 0;
  virtual void signal_end(const Frame& frame, double rx_power_dbm) = 0;

 protected:
  explicit PhyCore(PhyListener& listener) : listener_(listener) {}

  // Carrier sense apart from the node's own transmission.
  [[nodiscard]] virtual bool senses_busy() const = 0;
  // Whether a frame is being received (threshold: any arriving; sinr: the locked one).
  [[nodiscard]] virtual bool receiving() const = 0;
  // The model's part of a transmission's start and end, before the core's reports.
  virtual void transmission_started() {}
  virtual void transmission_ended() {}
  // Tells the listener if medium_busy() changed since it last heard.
  void report_busy_change();

  PhyListener& listener_;
  bool transmitting_ = false;
  bool reported_busy_ = false;
};

const char* to_string(PhyCore::State state);

}  // namespace swarmnet
