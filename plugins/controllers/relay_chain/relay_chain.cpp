#include "relay_chain.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lane_drive.hpp"

namespace swarmnet::relay_chain {

namespace {

Mode parse_mode(const std::string& text) {
  if (text == "none") return Mode::none;
  if (text == "geometric") return Mode::geometric;
  if (text == "link_aware") return Mode::link_aware;
  // The parameter's choices admit nothing else; a new choice without a mode must not pass as
  // link_aware.
  throw std::invalid_argument("relay_chain: mode '" + text +
                              "' is none of none, geometric, "
                              "link_aware");
}

}  // namespace

PluginInfo RelayChain::info() {
  return PluginInfo{
      "relay_chain",
      "1.0.0",
      "A leader explores along +x while relays keep it connected to a base (robot 0): by "
      "geometry, or from what each robot's radio measures of its upstream link.",
      "Robot 0 is the base, robot 1 the leader, robots 2.. the relays in chain order; each keeps "
      "the lane (y) it started on. mode none: relays stay, the leader goes spacing_m. geometric: "
      "relay k drives to k * spacing_m, the leader to (relays + 1) * spacing_m. link_aware "
      "(needs network.neighbors.enabled): all leave together; a relay anchors where its upstream "
      "(the base, or the previous relay) is weak, or unheard for lost_after_s: smoothed RSSI below "
      "rssi_threshold_dbm, or fewer than min_first_attempt_share of at least 4 unicast "
      "exchanges acknowledged at the first attempt; an anchored relay whose upstream stays "
      "unheard lost_after_s backs towards the base until the link is good with hysteresis_db to "
      "spare. The leader goes on while its upstream link (the last relay's) is good and waits "
      "where it is not. Nothing goes beyond goal_distance_m. The leader sends the base a "
      "report_bytes report every report_interval_s with a send report, and asks route_to(0) "
      "every step.\n"
      "Metrics: leader distance_m, route_to_base, connected_distance_m, report_acknowledged, "
      "series leader_distance_m and route_to_base; base reports_received; relays "
      "anchor_distance_m, retreats, series upstream_rssi_dbm (link_aware).",
      {text_param("mode", "link_aware", "none, geometric or link_aware",
                  {"none", "geometric", "link_aware"}),
       real_param("goal_distance_m", 1500.0, "m", "how far along +x the goal is", 1.0),
       real_param("speed_mps", 2.0, "m/s", "driving speed", 0.01),
       real_param("spacing_m", 180.0, "m",
                  "geometric and none: the radio range assumed (a relay every spacing_m)", 1.0),
       real_param("rssi_threshold_dbm", -85.0, "dBm",
                  "link_aware: a link is weak below this smoothed RSSI", -200.0, 50.0),
       real_param("min_first_attempt_share", 0.5, "",
                  "link_aware: a link is weak below this share of first-attempt "
                  "acknowledgements (with 4 exchanges or more)",
                  0.0, 1.0),
       real_param("hysteresis_db", 3.0, "dB",
                  "link_aware: a weak link counts as good again only this much above the "
                  "threshold",
                  0.0, 60.0),
       real_param("lost_after_s", 3.0, "s",
                  "link_aware: an anchored relay backs off after its upstream is unheard this "
                  "long",
                  0.0),
       real_param("grace_s", 5.0, "s",
                  "link_aware: no anchoring before this time (the tables fill first)", 0.0),
       real_param("report_interval_s", 1.0, "s", "leader: time between reports", 0.01),
       integer_param("report_bytes", 64, "B", "leader: report payload", 1, kMaxPayloadBytes),
       real_param("sample_interval_s", 1.0, "s", "time between samples of the series", 0.01)}};
}

RelayChain::RelayChain(const PluginArgs& args)
    : mode_(parse_mode(args.params.text("mode"))),
      goal_distance_m_(args.params.real("goal_distance_m")),
      speed_mps_(args.params.real("speed_mps")),
      spacing_m_(args.params.real("spacing_m")),
      criteria_{args.params.real("rssi_threshold_dbm"), args.params.real("min_first_attempt_share"),
                4},
      hysteresis_db_(args.params.real("hysteresis_db")),
      lost_after_s_(args.params.real("lost_after_s")),
      grace_s_(args.params.real("grace_s")),
      report_interval_s_(args.params.real("report_interval_s")),
      report_bytes_(args.params.integer("report_bytes")),
      sample_interval_s_(args.params.real("sample_interval_s")) {}

void RelayChain::init(RobotContext& robot) {
  role_ = chain_role(robot.id(), robot.robot_count());
  start_ = robot.position();
}

void RelayChain::reset() {
  motion_ = Motion::advancing;
  unheard_since_s_ = -1.0;
  next_report_s_ = 1.0;
  next_sample_s_ = 0.0;
  route_valid_ = false;
}

double RelayChain::distance(const RobotContext& robot) const {
  return robot.position().x() - start_.x();
}

bool RelayChain::sample_due(const RobotContext& robot) {
  if (to_seconds(robot.now()) < next_sample_s_) return false;
  next_sample_s_ += sample_interval_s_;
  return true;
}

void RelayChain::drive_to_distance(RobotContext& robot, double target_m) {
  drive_lane(robot, start_.x() + std::min(target_m, goal_distance_m_), start_.y(), speed_mps_);
}

void RelayChain::control_step(RobotContext& robot) {
  switch (role_.role) {
    case Role::base:
      step_base(robot);
      break;
    case Role::leader:
      step_leader(robot);
      break;
    case Role::relay:
      step_relay(robot);
      break;
  }
}

void RelayChain::step_base(RobotContext& robot) {
  robot.set_wheel_speeds(0.0, 0.0);
  for (const ReceivedMessage& message : robot.inbox()) {
    if (message.source == 1 && message.destination == robot.id()) {
      robot.record("reports_received", 1.0);
    }
  }
}

void RelayChain::step_leader(RobotContext& robot) {
  const double d = distance(robot);
  robot.record("distance_m", d);
  const Route route = robot.route_to(0);
  if (route.status != RouteStatus::pending) {
    route_valid_ = route.status == RouteStatus::valid;
    robot.record("route_to_base", route_valid_ ? 1.0 : 0.0);
    if (route_valid_) robot.record("connected_distance_m", d);
  }
  for (const SendReport& report : robot.send_reports()) {
    robot.record("report_acknowledged", report.outcome == SendOutcome::acknowledged ? 1.0 : 0.0);
  }
  if (to_seconds(robot.now()) >= next_report_s_) {
    next_report_s_ += report_interval_s_;
    const std::vector<std::byte> payload(static_cast<std::size_t>(report_bytes_));
    (void)robot.send(0, payload, SendOptions{0, true});
  }
  if (sample_due(robot)) {
    robot.sample("leader_distance_m", d);
    robot.sample("route_to_base", route_valid_ ? 1.0 : 0.0);
  }
  const double relays = static_cast<double>(robot.robot_count() - 2);
  switch (mode_) {
    case Mode::none:
      drive_to_distance(robot, spacing_m_);
      break;
    case Mode::geometric:
      drive_to_distance(robot, (relays + 1.0) * spacing_m_);
      break;
    case Mode::link_aware:
      follow_link(robot, false);
      break;
  }
}

void RelayChain::step_relay(RobotContext& robot) {
  switch (mode_) {
    case Mode::none:
      robot.set_wheel_speeds(0.0, 0.0);
      break;
    case Mode::geometric: {
      const double slot =
          std::min(static_cast<double>(role_.relay_index) * spacing_m_, goal_distance_m_);
      drive_to_distance(robot, slot);
      if (motion_ == Motion::advancing && std::abs(distance(robot) - slot) <= kArrivedM) {
        motion_ = Motion::anchored;
        robot.record("anchor_distance_m", distance(robot));
      }
      break;
    }
    case Mode::link_aware:
      follow_link(robot, true);
      if (sample_due(robot)) {
        const RadioNeighbor* upstream = find_neighbor(robot.neighbors(), role_.upstream);
        if (upstream != nullptr) robot.sample("upstream_rssi_dbm", upstream->rssi_smoothed_dbm);
      }
      break;
  }
}

void RelayChain::follow_link(RobotContext& robot, bool may_retreat) {
  const double now_s = to_seconds(robot.now());
  const double d = distance(robot);
  const std::span<const RadioNeighbor> table = robot.neighbors();
  const double margin = motion_ == Motion::advancing ? 0.0 : hysteresis_db_;
  const LinkState link = judge_link(table, role_.upstream, criteria_, margin);
  if (link == LinkState::unheard) {
    if (unheard_since_s_ < 0.0) unheard_since_s_ = now_s;
  } else {
    unheard_since_s_ = -1.0;
  }
  switch (motion_) {
    case Motion::advancing:
      // A weak link stops it at once; an unheard one only once lost_after_s has passed, since
      // a few missed frames (a collision, a fade) empty the table of a neighbour that is there.
      if (d >= goal_distance_m_ - kArrivedM ||
          (now_s >= grace_s_ &&
           (link == LinkState::weak ||
            (link == LinkState::unheard && now_s - unheard_since_s_ >= lost_after_s_)))) {
        motion_ = Motion::anchored;
        robot.record("anchor_distance_m", d);
        robot.set_wheel_speeds(0.0, 0.0);
      } else {
        drive_to_distance(robot, goal_distance_m_);
      }
      break;
    case Motion::anchored:
      robot.set_wheel_speeds(0.0, 0.0);
      if (!may_retreat && link == LinkState::good && d < goal_distance_m_ - kArrivedM) {
        motion_ = Motion::advancing;  // the leader goes on once its link is good again
      } else if (may_retreat && link == LinkState::unheard && d > kArrivedM &&
                 now_s - unheard_since_s_ >= lost_after_s_) {
        // At the base there is nowhere further back to go: it waits there.
        motion_ = Motion::retreating;
        robot.record("retreats", 1.0);
      }
      break;
    case Motion::retreating:
      if (link == LinkState::good || d <= kArrivedM) {
        motion_ = Motion::anchored;
        robot.record("anchor_distance_m", d);
        robot.set_wheel_speeds(0.0, 0.0);
      } else {
        drive_to_distance(robot, 0.0);
      }
      break;
  }
}

}  // namespace swarmnet::relay_chain

SWARMNET_PLUGIN(swarmnet::relay_chain::RelayChain)
