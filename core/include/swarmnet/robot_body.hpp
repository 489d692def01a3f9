// A robot's physical state, as the physics engine sees it.
#pragma once

#include "swarmnet/vector.hpp"

namespace swarmnet {

// A differential-drive disc (foot-bot-like defaults come from the scenario).
struct RobotBody {
  Vec2 position = Vec2::Zero();  // centre, m
  double heading_rad = 0.0;      // counter-clockwise from +x
  double radius_m = 0.085;
  double axle_m = 0.14;        // distance between the wheels
  double max_speed_mps = 1.0;  // per wheel
  double left_mps = 0.0;       // commanded wheel speeds, already clamped to max_speed_mps
  double right_mps = 0.0;
};

}  // namespace swarmnet
