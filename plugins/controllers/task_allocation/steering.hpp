// steering: go-to-point for a differential drive, with proximity avoidance.
//
// Go-to-point: with heading error e towards the target, the robot turns in place when
// |e| > 45 degrees, else drives at max_speed_mps() while steering proportionally; the turn rate
// is e / tau with tau = max(0.25 s, 2 steps) (the error decays over a few steps, never
// overshooting in one) and the forward speed is lowered so that neither wheel exceeds
// max_speed_mps() and the robot does not pass the target within one tau.
//
// Avoidance has priority: when a proximity ray within 60 degrees of the heading reads less than
// 0.5 m (capped to the sensor's range, which means clear), the robot turns in place away from the
// closer side (ties: to the left; at most 22.5 degrees a step), backing off at a fifth of its speed
// when the reading is below half of that; it keeps the side until the front is clear, then drives
// straight on for 1 m before steering to the target again, so robots do not jam nose to nose by an
// event or against a wall.
#pragma once

#include <span>

#include "swarmnet/controller.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet::task_allocation {

struct WheelSpeeds {
  double left_mps = 0.0;
  double right_mps = 0.0;
  bool operator==(const WheelSpeeds&) const = default;
};

// Closer than this in the front sector: avoid.
inline constexpr double kAvoidDistanceM = 0.5;

// Go-to-point without avoidance (see the top of this file).
[[nodiscard]] WheelSpeeds steer_to(const Vec2& position, double heading_rad, const Vec2& target,
                                   double max_speed_mps, double axle_m, double step_s);

class Steering {
 public:
  // Drives `robot` towards `target`, avoiding what its proximity ring sees.
  void drive(RobotContext& robot, const Vec2& target);
  static void stop(RobotContext& robot) { robot.set_wheel_speeds(0.0, 0.0); }

  bool operator==(const Steering&) const = default;

 private:
  bool avoiding_ = false;
  double turn_sign_ = 1.0;        // +1 left (counter-clockwise), -1 right
  double escape_until_s_ = -1.0;  // driving straight after avoiding, until then
};

}  // namespace swarmnet::task_allocation
