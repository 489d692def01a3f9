// Driving along a lane: a differential drive steered to a point on the line y = lane_y, forward
// in +x (towards the goal) or back. Turns in place when the heading error exceeds 45 degrees,
// else drives at `speed_mps` while steering proportionally; the turn rate is error / tau with
// tau = max(0.25 s, 2 steps), so the error decays over a few steps without overshooting.
#pragma once

#include "swarmnet/controller.hpp"

namespace swarmnet::relay_chain {

// Within this of the target x the robot stops.
inline constexpr double kArrivedM = 0.5;

struct Wheels {
  double left_mps = 0.0;
  double right_mps = 0.0;
};

// Wheel speeds towards (target_x, lane_y) from `position` and `heading_rad`; zero once within
// kArrivedM of target_x.
[[nodiscard]] Wheels lane_wheels(const Vec2& position, double heading_rad, double target_x,
                                 double lane_y, double speed_mps, double axle_m, double step_s);

inline void drive_lane(RobotContext& robot, double target_x, double lane_y, double speed_mps) {
  const Wheels w = lane_wheels(robot.position(), robot.heading_rad(), target_x, lane_y, speed_mps,
                               robot.axle_m(), robot.step_s());
  robot.set_wheel_speeds(w.left_mps, w.right_mps);
}

}  // namespace swarmnet::relay_chain
