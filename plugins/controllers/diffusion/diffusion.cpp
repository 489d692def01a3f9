#include "diffusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace swarmnet::diffusion {

namespace {

double wrap_angle(double angle_rad) { return std::remainder(angle_rad, 2.0 * std::numbers::pi); }

// A random turn ends when the heading is this close to its target, or has passed it.
constexpr double kHeadingToleranceRad = 0.02;

// Left and right readings closer than this count as equal. Ray directions are computed from the
// heading, so mirror-image rays differ in their last bits and exact equality would almost never
// occur: a head-on wall would then always be avoided on the side rounding happens to favour.
constexpr double kSymmetryToleranceM = 1e-6;

}  // namespace

PluginInfo Diffusion::info() {
  return PluginInfo{
      "diffusion",
      "1.0.0",
      "Random-walk diffusion with proximity-based obstacle avoidance (the RoboNetSim mobility).",
      "The robot drives straight at speed_mps. Obstacle avoidance has priority: when any "
      "proximity ray whose bearing lies within front_half_angle_rad of the heading reads less "
      "than avoid_distance_m (and less than the sensor's range, which means 'clear'), the robot "
      "turns in place, its wheels at -/+ turn_speed_mps, away from the side with the closer "
      "reading (rays to the left of the heading against rays to the right; straight ahead counts "
      "for neither). When both sides read the same (within 1 micrometre) it picks a side at "
      "random. The side is kept "
      "until the front sector is clear, so the robot does not dither in corners. The default "
      "45 degree sector holds everything the body could hit within avoid_distance_m (further than "
      "4 cm away) while ignoring robots and walls merely alongside.\n"
      "Diffusion: at intervals drawn from an exponential distribution with mean turn_interval_s "
      "(a Poisson process of turns; 0 disables them) the robot picks a heading uniformly at "
      "random and turns in place towards it, the shorter way, then drives on. Avoidance cancels "
      "a random turn in progress.\n"
      "Random draws (turn times, headings, sides) come from the robot's own stream, so runs are "
      "reproducible and one robot's choices do not depend on another's. Wheel speeds are clamped "
      "to the robot's max_speed_mps.",
      {real_param("speed_mps", 1.0, "m/s", "cruising speed of both wheels", 0.0),
       real_param("turn_speed_mps", 0.2, "m/s",
                  "wheel speed when turning in place (one wheel forward, one backward)", 1e-3),
       real_param("avoid_distance_m", 0.5, "m",
                  "turn away when a front ray reads less than this distance from the body", 0.0),
       real_param("front_half_angle_rad", std::numbers::pi / 4.0, "rad",
                  "half-angle of the front sector around the heading", 0.0, std::numbers::pi),
       real_param("turn_interval_s", 10.0, "s",
                  "mean time between random heading changes (exponential); 0 disables them", 0.0)}};
}

Diffusion::Diffusion(const PluginArgs& args)
    : speed_mps_(args.params.real("speed_mps")),
      turn_speed_mps_(args.params.real("turn_speed_mps")),
      avoid_distance_m_(args.params.real("avoid_distance_m")),
      front_half_angle_rad_(args.params.real("front_half_angle_rad")),
      turn_interval_s_(args.params.real("turn_interval_s")),
      state_{RandomStream(args.seed)},
      initial_{state_} {}

void Diffusion::init(RobotContext& robot) {
  const std::size_t rays = robot.proximity().size();
  const double spacing_rad = 2.0 * std::numbers::pi / static_cast<double>(rays);
  ray_sides_.assign(rays, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < rays; ++k) {
    const double bearing_rad = wrap_angle(spacing_rad * static_cast<double>(k));
    // The tolerance keeps a ray lying exactly on the sector's edge inside it despite rounding.
    if (std::abs(bearing_rad) > front_half_angle_rad_ + 1e-9) continue;
    ray_sides_[k] = bearing_rad > 0.0 ? 1.0 : bearing_rad < 0.0 ? -1.0 : 0.0;
  }
  state_.mode = Mode::driving;
  schedule_random_turn(to_seconds(robot.now()));
  initial_ = state_;
}

void Diffusion::reset() { state_ = initial_; }

void Diffusion::schedule_random_turn(double now_s) {
  state_.next_random_turn_s = turn_interval_s_ > 0.0
                                  ? now_s + state_.random.exponential(1.0 / turn_interval_s_)
                                  : std::numeric_limits<double>::infinity();
}

Diffusion::FrontView Diffusion::look_ahead(const RobotContext& robot) const {
  const std::span<const double> rays = robot.proximity();
  // A reading equal to the range means nothing was seen.
  const double threshold_m = std::min(avoid_distance_m_, robot.proximity_range_m());
  double left_m = std::numeric_limits<double>::infinity();
  double right_m = std::numeric_limits<double>::infinity();
  FrontView view;
  for (std::size_t k = 0; k < std::min(rays.size(), ray_sides_.size()); ++k) {
    const double side = ray_sides_[k];
    if (std::isnan(side)) continue;
    if (rays[k] < threshold_m) view.blocked = true;
    if (side > 0.0) left_m = std::min(left_m, rays[k]);
    if (side < 0.0) right_m = std::min(right_m, rays[k]);
  }
  if (left_m < right_m - kSymmetryToleranceM) view.away_sign = -1.0;
  if (right_m < left_m - kSymmetryToleranceM) view.away_sign = 1.0;
  return view;
}

void Diffusion::turn(RobotContext& robot) const {
  robot.set_wheel_speeds(-state_.turn_sign * turn_speed_mps_, state_.turn_sign * turn_speed_mps_);
}

void Diffusion::control_step(RobotContext& robot) {
  const double now_s = to_seconds(robot.now());
  const FrontView front = look_ahead(robot);
  if (front.blocked) {
    if (state_.mode != Mode::avoiding) {
      state_.mode = Mode::avoiding;
      state_.turn_sign = front.away_sign != 0.0         ? front.away_sign
                         : state_.random.bernoulli(0.5) ? 1.0
                                                        : -1.0;
    }
    turn(robot);
    return;
  }
  if (state_.mode == Mode::avoiding) state_.mode = Mode::driving;

  if (now_s >= state_.next_random_turn_s) {
    state_.mode = Mode::random_turn;
    state_.target_heading_rad = state_.random.uniform(-std::numbers::pi, std::numbers::pi);
    state_.turn_sign =
        wrap_angle(state_.target_heading_rad - robot.heading_rad()) >= 0.0 ? 1.0 : -1.0;
    schedule_random_turn(now_s);
  }
  if (state_.mode == Mode::random_turn) {
    const double error_rad = wrap_angle(state_.target_heading_rad - robot.heading_rad());
    const bool passed = error_rad * state_.turn_sign < 0.0;
    if (!passed && std::abs(error_rad) > kHeadingToleranceRad) {
      turn(robot);
      return;
    }
    state_.mode = Mode::driving;
  }
  robot.set_wheel_speeds(speed_mps_, speed_mps_);
}

}  // namespace swarmnet::diffusion

SWARMNET_PLUGIN(swarmnet::diffusion::Diffusion)
