// relay_chain: a leader explores along +x towards a far goal while relays keep it connected to a
// base, the reference study's next step (§VII: control that keeps communication reliable), with
// the link information a controller can sense. Three modes share everything but the decision:
//
//   none        relays stay at the base; the leader goes one assumed radio range (spacing_m).
//   geometric   the disk assumption: relay k drives to k * spacing_m, the leader to
//               (relays + 1) * spacing_m; no radio information is used.
//   link_aware  relays and leader leave together; each relay stops (anchors) where its radio's
//               measurement of its upstream link (neighbors(): smoothed RSSI, first-attempt
//               acknowledgement share) falls below the criteria or stays unheard
//               for lost_after_s, and backs towards the base
//               while its upstream is unheard for lost_after_s; the leader goes on while its
//               own upstream link is good (the last relay's, or the base's) and stops there.
//
// Every robot keeps its own lane (the y it started at) and stops at goal_distance_m from where
// it started. The leader sends the base a report every report_interval_s (unicast, with a send
// report) and asks route_to(base) every step. Metrics:
//   leader: distance_m (each step; max = distance reached), route_to_base (1/0 per answered
//   step; mean = share of time a route existed), connected_distance_m (distance at steps with a
//   route; max = farthest connected), report_acknowledged (1/0 per send report), series
//   leader_distance_m and route_to_base every sample_interval_s;
//   base: reports_received; relays: anchor_distance_m (each anchoring), retreats, series
//   upstream_rssi_dbm (link_aware).
#pragma once

#include <cstdint>
#include <string>

#include "chain_role.hpp"
#include "link_judge.hpp"
#include "swarmnet/controller.hpp"

namespace swarmnet::relay_chain {

enum class Mode : std::uint8_t { none, geometric, link_aware };

class RelayChain final : public Controller {
 public:
  static PluginInfo info();
  explicit RelayChain(const PluginArgs& args);

  void init(RobotContext& robot) override;
  void control_step(RobotContext& robot) override;
  void reset() override;

 private:
  enum class Motion : std::uint8_t { advancing, anchored, retreating };

  [[nodiscard]] double distance(const RobotContext& robot) const;
  void step_base(RobotContext& robot);
  void step_leader(RobotContext& robot);
  void step_relay(RobotContext& robot);
  // link_aware: advances while the upstream link is good, anchors where it is not.
  void follow_link(RobotContext& robot, bool may_retreat);
  void drive_to_distance(RobotContext& robot, double target_m);
  [[nodiscard]] bool sample_due(const RobotContext& robot);

  Mode mode_;
  double goal_distance_m_;
  double speed_mps_;
  double spacing_m_;
  LinkCriteria criteria_;
  double hysteresis_db_;
  double lost_after_s_;
  double grace_s_;
  double report_interval_s_;
  std::int64_t report_bytes_;
  double sample_interval_s_;

  ChainRole role_;
  Vec2 start_ = Vec2::Zero();
  Motion motion_ = Motion::advancing;
  double unheard_since_s_ = -1.0;  // link_aware: when the upstream left the table (-1: heard)
  double next_report_s_ = 1.0;
  double next_sample_s_ = 0.0;
  bool route_valid_ = false;  // leader: the last answer of route_to(base)
};

}  // namespace swarmnet::relay_chain
