#include "lane_drive.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swarmnet::relay_chain {

Wheels lane_wheels(const Vec2& position, double heading_rad, double target_x, double lane_y,
                   double speed_mps, double axle_m, double step_s) {
  const double dx = target_x - position.x();
  if (std::abs(dx) <= kArrivedM) return {};
  // Aim a few metres ahead on the lane, so that a robot off its lane merges back smoothly.
  const double look_ahead = std::copysign(std::min(std::abs(dx), 5.0), dx);
  const double want = std::atan2(lane_y - position.y(), look_ahead);
  const double error = std::remainder(want - heading_rad, 2.0 * std::numbers::pi);
  const double tau = std::max(0.25, 2.0 * step_s);
  const double turn = error / tau;
  const double forward =
      std::abs(error) > std::numbers::pi / 4.0 ? 0.0 : speed_mps * std::cos(error);
  const double half = turn * axle_m / 2.0;
  // Scale so that neither wheel exceeds the speed asked for.
  const double biggest = std::max(std::abs(forward - half), std::abs(forward + half));
  const double scale = biggest > speed_mps ? speed_mps / biggest : 1.0;
  return {(forward - half) * scale, (forward + half) * scale};
}

}  // namespace swarmnet::relay_chain
