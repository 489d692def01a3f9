// Differential-drive kinematics integrated exactly over one step.
//
// With wheel speeds l and r and axle length b, the body moves at v = (l + r) / 2 and turns at
// w = (r - l) / b. Over dt both are constant, so the centre follows a circular arc (a straight
// line when l == r). The displacement is the chord of that arc:
//
//   d = v dt * sinc(w dt / 2),  along the mid-step heading theta + w dt / 2,
//
// which is the closed form R (sin(theta + w dt) - sin theta, cos theta - cos(theta + w dt)) with
// R = v / w rewritten so that it stays accurate as w -> 0 (no division by a tiny w) and is
// exactly the straight segment v dt when w == 0.
#pragma once

#include <cmath>
#include <numbers>

#include "swarmnet/robot_body.hpp"

namespace swarmnet::kinematic2d {

// sin(x) / x, accurate near zero (the Taylor remainder below 1e-4 is under 1e-18).
inline double sinc(double x) {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

// An angle mapped into [-pi, pi].
inline double wrap_angle(double angle_rad) {
  return std::remainder(angle_rad, 2.0 * std::numbers::pi);
}

// Moves `body` along its drive arc for dt_s seconds; collisions are not considered here.
inline void integrate_drive(RobotBody& body, double dt_s) {
  const double speed_mps = 0.5 * (body.left_mps + body.right_mps);
  const double turn_rad = (body.right_mps - body.left_mps) / body.axle_m * dt_s;
  const double mid_heading_rad = body.heading_rad + 0.5 * turn_rad;
  const double chord_m = speed_mps * dt_s * sinc(0.5 * turn_rad);
  body.position.x() += chord_m * std::cos(mid_heading_rad);
  body.position.y() += chord_m * std::sin(mid_heading_rad);
  body.heading_rad = wrap_angle(body.heading_rad + turn_rad);
}

}  // namespace swarmnet::kinematic2d
