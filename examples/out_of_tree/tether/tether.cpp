#include "tether.hpp"

#include <array>
#include <cmath>

namespace example::tether {

using namespace swarmnet;

PluginInfo Tether::info() {
  return PluginInfo{
      "tether",
      "1.0.0",
      "Robots spread out and stop before their radios lose the others",
      "Every robot but `anchor` drives straight ahead at speed_fraction of its top speed and "
      "stops for good (after grace_s, while the tables fill) when its radio hears fewer than "
      "min_neighbors robots with a smoothed RSSI of rssi_floor_dbm or better, or when its "
      "routing protocol's route to the anchor is longer than max_hops. The anchor stays. Every "
      "robot sends a one-hop beacon (1 byte, hop limit 1) every beacon_interval_s so that it "
      "is heard, and the others send the anchor a check-in (1 byte, unicast, with a send "
      "report) every check_in_interval_s, which is what makes a reactive protocol (AODV) look "
      "for a route; they ask route_to(anchor) every step. Needs network.neighbors.enabled. "
      "Metrics: route_to_anchor (each answered step of a robot other than the anchor: 1 with a "
      "valid route), distance_from_start_m (each step), check_ins_acknowledged and "
      "check_ins_dropped (their send reports: the first hop acknowledged, or the robot's stack "
      "gave up), stopped_at_m (once, where a robot stopped); series strong_neighbors.",
      {
          integer_param("anchor", 0, "", "id of the robot that stays", 0, 1000000),
          integer_param("min_neighbors", 2, "", "robots a moving robot must hear well", 1, 1024),
          integer_param("max_hops", 3, "", "longest route to the anchor a moving robot accepts", 1,
                        255),
          real_param("rssi_floor_dbm", -75.0, "dBm", "a neighbour heard weaker is not counted",
                     -200.0, 50.0),
          real_param("speed_fraction", 0.5, "", "share of max_speed_mps used", 0.0, 1.0),
          real_param("beacon_interval_s", 0.5, "s", "time between beacons", 0.01, 3600.0),
          real_param("check_in_interval_s", 2.0, "s", "time between check-ins with the anchor",
                     0.01, 3600.0),
          real_param("grace_s", 2.0, "s", "no stopping before this time", 0.0),
      }};
}

Tether::Tether(const PluginArgs& args)
    : anchor_(static_cast<RobotId>(args.params.integer("anchor"))),
      min_neighbors_(static_cast<int>(args.params.integer("min_neighbors"))),
      max_hops_(static_cast<int>(args.params.integer("max_hops"))),
      rssi_floor_dbm_(args.params.real("rssi_floor_dbm")),
      speed_fraction_(args.params.real("speed_fraction")),
      beacon_interval_s_(args.params.real("beacon_interval_s")),
      check_in_interval_s_(args.params.real("check_in_interval_s")),
      grace_s_(args.params.real("grace_s")) {}

void Tether::init(RobotContext& robot) {
  start_ = robot.position();
  next_beacon_s_ = to_seconds(robot.now());
  next_check_in_s_ = to_seconds(robot.now());
}

void Tether::reset() {
  next_beacon_s_ = 0.0;
  next_check_in_s_ = 0.0;
  stopped_ = false;
}

int Tether::strong_neighbors(const RobotContext& robot) const {
  int strong = 0;
  for (const RadioNeighbor& n : robot.neighbors()) {
    if (n.rssi_smoothed_dbm >= rssi_floor_dbm_) ++strong;
  }
  return strong;
}

void Tether::beacon(RobotContext& robot) {
  if (to_seconds(robot.now()) + 1e-9 < next_beacon_s_) return;
  next_beacon_s_ += beacon_interval_s_;
  const std::array<std::byte, 1> hello{std::byte{'T'}};
  (void)robot.send(kBroadcast, hello, SendOptions{1, false});
}

void Tether::check_in(RobotContext& robot) {
  // Only check-ins ask for reports, so every report is about one.
  for (const SendReport& report : robot.send_reports()) {
    robot.record(
        report.outcome == SendOutcome::dropped ? "check_ins_dropped" : "check_ins_acknowledged",
        1.0);
  }
  if (to_seconds(robot.now()) + 1e-9 < next_check_in_s_) return;
  next_check_in_s_ += check_in_interval_s_;
  const std::array<std::byte, 1> here{std::byte{'C'}};
  (void)robot.send(anchor_, here, SendOptions{0, true});
}

void Tether::control_step(RobotContext& robot) {
  beacon(robot);
  const int strong = strong_neighbors(robot);
  robot.sample("strong_neighbors", strong);
  robot.record("distance_from_start_m", (robot.position() - start_).norm());
  if (robot.id() == anchor_) {
    robot.set_wheel_speeds(0.0, 0.0);
    return;
  }
  check_in(robot);
  // The first call for a destination is pending; from then on each step has the answer.
  const Route route = robot.route_to(anchor_);
  if (route.status != RouteStatus::pending) {
    robot.record("route_to_anchor", route.status == RouteStatus::valid ? 1.0 : 0.0);
  }
  const bool too_far =
      route.status == RouteStatus::valid && static_cast<int>(route.hops) > max_hops_;
  if (!stopped_ && to_seconds(robot.now()) >= grace_s_ && (strong < min_neighbors_ || too_far)) {
    stopped_ = true;
    robot.record("stopped_at_m", (robot.position() - start_).norm());
  }
  const double v = stopped_ ? 0.0 : speed_fraction_ * robot.max_speed_mps();
  robot.set_wheel_speeds(v, v);
}

}  // namespace example::tether

SWARMNET_PLUGIN(example::tether::Tether)
