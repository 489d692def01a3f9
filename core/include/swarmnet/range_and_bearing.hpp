// The range-and-bearing device, as ARGoS's foot-bot and e-puck carry one: every robot has an
// emitter that sends a few data bytes and a receiver that reads, from each robot whose emitter
// it can see, that robot's id, its distance and its bearing. It is a line-of-sight device of the
// robot half (infrared, in the real robots): it is not the radio, sends nothing through the
// network half and costs nothing there. Scenario keys robots.range_and_bearing (docs/scenario.md);
// controllers read it with RobotContext::range_and_bearing() and set their data with
// RobotContext::set_range_and_bearing_data() (docs/plugins.md, "Range and bearing").
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "swarmnet/ids.hpp"

namespace swarmnet {

// The most data bytes one emitter may carry (robots.range_and_bearing.data_bytes' range). The
// device is for a few bytes a step, as its hardware is; larger payloads go by send().
inline constexpr std::uint32_t kMaxRangeAndBearingDataBytes = 256;

// One robot seen by this robot's receiver at the start of the step.
struct RangeAndBearingReading {
  RobotId robot = kNoNode;   // whose emitter
  double range_m = 0.0;      // centre to centre, with the scenario's noise; never negative
  double bearing_rad = 0.0;  // of that centre, from this robot's heading, counter-clockwise,
                             // in (-pi, pi], with the scenario's noise
  // What that robot set with set_range_and_bearing_data() up to its previous step, zero-padded
  // to exactly data_bytes bytes. Valid until this step ends (copy what you keep).
  std::span<const std::byte> data;
};

}  // namespace swarmnet
