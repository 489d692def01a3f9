// The robots' motion as an ns-2 mobility trace (the format ns-2's setdest and ns-3's
// Ns2MobilityHelper read), so the same motion can be replayed in another network simulator.
//
//   $node_(i) set X_ x / set Y_ y / set Z_ 0     initial positions
//   $ns_ at t "$node_(i) setdest x y speed"       move in a straight line, reaching (x, y) at
//                                                 the next sample time
// One sample every `interval` steps; a node that does not move between two samples gets no line.
#pragma once

#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

class MobilityTraceWriter {
 public:
  MobilityTraceWriter(std::ostream& out, std::uint64_t interval_steps, double step_s);

  // Positions of every robot at the start of step `step`; call for every step in order.
  void sample(std::uint64_t step, std::span<const Vec2> positions);

 private:
  std::ostream& out_;
  std::uint64_t interval_steps_;
  double step_s_;
  std::vector<Vec2> previous_;
  std::uint64_t previous_step_ = 0;
  std::string text_;  // one sample's lines, written at once (capacity kept)
};

}  // namespace swarmnet
