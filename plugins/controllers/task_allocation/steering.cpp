#include "steering.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace swarmnet::task_allocation {

namespace {

constexpr double kTurnInPlaceRad = std::numbers::pi / 4.0;
constexpr double kFrontHalfAngleRad = std::numbers::pi / 3.0;
constexpr double kEscapeDistanceM = 1.0;
constexpr double kBackOffFraction = 0.2;
constexpr double kAvoidTurnPerStepRad = std::numbers::pi / 8.0;

double wrap_angle(double angle_rad) { return std::remainder(angle_rad, 2.0 * std::numbers::pi); }

double time_constant_s(double step_s) { return std::max(0.25, 2.0 * step_s); }

// Wheel speeds for forward speed v and turn rate w (counter-clockwise positive).
WheelSpeeds wheels(double v_mps, double w_radps, double axle_m) {
  return {v_mps - 0.5 * w_radps * axle_m, v_mps + 0.5 * w_radps * axle_m};
}

}  // namespace

WheelSpeeds steer_to(const Vec2& position, double heading_rad, const Vec2& target,
                     double max_speed_mps, double axle_m, double step_s) {
  const Vec2 offset = target - position;
  const double distance_m = offset.norm();
  if (distance_m < 1e-9) return {};
  const double error_rad = wrap_angle(std::atan2(offset.y(), offset.x()) - heading_rad);
  const double tau_s = time_constant_s(step_s);
  const double max_turn_radps = 2.0 * max_speed_mps / axle_m;
  const double w_radps = std::clamp(error_rad / tau_s, -max_turn_radps, max_turn_radps);
  if (std::abs(error_rad) > kTurnInPlaceRad) return wheels(0.0, w_radps, axle_m);
  const double v_mps =
      std::max(0.0, std::min(max_speed_mps - 0.5 * std::abs(w_radps) * axle_m, distance_m / tau_s));
  return wheels(v_mps, w_radps, axle_m);
}

void Steering::drive(RobotContext& robot, const Vec2& target) {
  const double now_s = to_seconds(robot.now());
  const double speed_mps = robot.max_speed_mps();
  const std::span<const double> rays = robot.proximity();
  const double threshold_m = std::min(kAvoidDistanceM, robot.proximity_range_m());
  const double spacing_rad =
      2.0 * std::numbers::pi / static_cast<double>(std::max<std::size_t>(1, rays.size()));
  double closest_m = std::numeric_limits<double>::infinity();
  double left_m = std::numeric_limits<double>::infinity();
  double right_m = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < rays.size(); ++k) {
    const double bearing_rad = wrap_angle(spacing_rad * static_cast<double>(k));
    if (std::abs(bearing_rad) > kFrontHalfAngleRad + 1e-9) continue;
    closest_m = std::min(closest_m, rays[k]);
    if (bearing_rad > 0.0) left_m = std::min(left_m, rays[k]);
    if (bearing_rad < 0.0) right_m = std::min(right_m, rays[k]);
  }
  if (closest_m < threshold_m) {
    if (!avoiding_) {
      avoiding_ = true;
      turn_sign_ = left_m < right_m ? -1.0 : 1.0;
    }
    // Wheels at -/+ speed / 2, but no more than kAvoidTurnPerStepRad in one step.
    const double w_radps =
        turn_sign_ * std::min(speed_mps / robot.axle_m(), kAvoidTurnPerStepRad / robot.step_s());
    const double v_mps = closest_m < 0.5 * threshold_m ? -kBackOffFraction * speed_mps : 0.0;
    const WheelSpeeds w = wheels(v_mps, w_radps, robot.axle_m());
    robot.set_wheel_speeds(w.left_mps, w.right_mps);
    return;
  }
  if (avoiding_) {
    avoiding_ = false;
    escape_until_s_ = speed_mps > 0.0 ? now_s + kEscapeDistanceM / speed_mps : now_s;
  }
  if (now_s < escape_until_s_) {
    robot.set_wheel_speeds(speed_mps, speed_mps);
    return;
  }
  const WheelSpeeds w = steer_to(robot.position(), robot.heading_rad(), target, speed_mps,
                                 robot.axle_m(), robot.step_s());
  robot.set_wheel_speeds(w.left_mps, w.right_mps);
}

}  // namespace swarmnet::task_allocation
