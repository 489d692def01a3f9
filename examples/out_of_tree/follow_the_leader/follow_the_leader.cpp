#include "follow_the_leader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

namespace example::follow_the_leader {

using namespace swarmnet;

namespace {

// A follower's fastest turn, rad/s: a half turn takes about 1.6 s.
constexpr double kMaxTurnRateRadS = 2.0;

// A beacon: the leader's x and y in metres, as two doubles.
std::array<std::byte, 16> encode(const Vec2& p) {
  std::array<std::byte, 16> bytes{};
  const double xy[2] = {p.x(), p.y()};
  std::memcpy(bytes.data(), xy, sizeof xy);
  return bytes;
}

std::optional<Vec2> decode(const std::vector<std::byte>& bytes) {
  if (bytes.size() != 16) return std::nullopt;
  double xy[2];
  std::memcpy(xy, bytes.data(), sizeof xy);
  return Vec2{xy[0], xy[1]};
}

}  // namespace

PluginInfo FollowTheLeader::info() {
  return PluginInfo{
      "follow_the_leader",
      "1.1.0",
      "One robot leads and beacons its position; the others drive towards it",
      "Robot `leader` drives a wide circle at speed_fraction of its top speed and broadcasts its "
      "position (16 bytes) every beacon_interval_s. Every other robot turns towards the last "
      "beaconed position it received (by half its heading error a step, at most 2 rad/s, "
      "slowing down as much as it faces away) and drives there, stopping within "
      "follow_distance_m; without news it waits. Metrics: distance_to_leader_m (each follower, "
      "each step, once it "
      "has heard a beacon: distance to the leader's last known position) and beacon_age_s (age "
      "of each beacon received).",
      {
          integer_param("leader", 0, "", "id of the leading robot", 0, 1000000),
          real_param("beacon_interval_s", 0.5, "s", "time between the leader's beacons", 0.01,
                     3600.0),
          real_param("follow_distance_m", 5.0, "m", "followers stop this close to the leader", 0.0),
          real_param("speed_fraction", 0.8, "", "share of max_speed_mps used", 0.0, 1.0),
      }};
}

FollowTheLeader::FollowTheLeader(const PluginArgs& args)
    : leader_(static_cast<RobotId>(args.params.integer("leader"))),
      beacon_interval_s_(args.params.real("beacon_interval_s")),
      follow_distance_m_(args.params.real("follow_distance_m")),
      speed_fraction_(args.params.real("speed_fraction")) {}

void FollowTheLeader::init(RobotContext& robot) { next_beacon_s_ = to_seconds(robot.now()); }

void FollowTheLeader::reset() {
  next_beacon_s_ = 0.0;
  leader_position_.reset();
}

void FollowTheLeader::control_step(RobotContext& robot) {
  if (robot.id() == leader_) {
    lead(robot);
  } else {
    follow(robot);
  }
}

void FollowTheLeader::lead(RobotContext& robot) {
  const double v = speed_fraction_ * robot.max_speed_mps();
  robot.set_wheel_speeds(0.9 * v, v);  // a wide left-hand circle
  if (to_seconds(robot.now()) + 1e-9 >= next_beacon_s_) {
    const auto beacon = encode(robot.position());
    robot.send(kBroadcast, beacon);
    next_beacon_s_ += beacon_interval_s_;
  }
}

void FollowTheLeader::follow(RobotContext& robot) {
  for (const ReceivedMessage& m : robot.inbox()) {
    if (m.source != leader_) continue;
    if (const auto p = decode(m.payload)) {
      leader_position_ = p;
      robot.record("beacon_age_s", to_seconds(robot.now() - m.sent_at));
    }
  }
  if (!leader_position_) {
    robot.set_wheel_speeds(0.0, 0.0);
    return;
  }
  const Vec2 to = *leader_position_ - robot.position();
  const double distance = to.norm();
  robot.record("distance_to_leader_m", distance);
  if (distance <= follow_distance_m_) {
    robot.set_wheel_speeds(0.0, 0.0);
    return;
  }
  // Heading error towards the leader, in [-pi, pi].
  const double error =
      std::remainder(std::atan2(to.y(), to.x()) - robot.heading_rad(), 2.0 * std::numbers::pi);
  // Turn by half the error this step, and by at most kMaxTurnRateRadS. A turn smaller than the
  // error never overshoots, so the heading settles on the leader's bearing; one of more than
  // twice the error would leave a larger error on the other side, and the robot would spin.
  const double max_turn = kMaxTurnRateRadS * robot.step_s();
  const double w = std::clamp(0.5 * error, -max_turn, max_turn) / robot.step_s();
  // Forwards only as much as it faces the leader: facing away, it turns on the spot.
  const double v = speed_fraction_ * robot.max_speed_mps() * std::max(0.0, std::cos(error));
  // Turn rate w from the wheels (swarmnet/controller.hpp). Should the clamp to max_speed_mps()
  // cut a wheel, the turn only gets smaller: still no overshoot.
  robot.set_wheel_speeds(v - w * robot.axle_m() / 2.0, v + w * robot.axle_m() / 2.0);
}

}  // namespace example::follow_the_leader

SWARMNET_PLUGIN(example::follow_the_leader::FollowTheLeader)
