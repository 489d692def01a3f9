// `follow_the_leader` controller (an out-of-tree example): one robot leads, driving a wide
// circle and broadcasting its position; the others drive towards the last position they heard.
#pragma once

#include <cstdint>
#include <optional>

#include "swarmnet/controller.hpp"

namespace example::follow_the_leader {

class FollowTheLeader final : public swarmnet::Controller {
 public:
  static swarmnet::PluginInfo info();
  explicit FollowTheLeader(const swarmnet::PluginArgs& args);

  void init(swarmnet::RobotContext& robot) override;
  void control_step(swarmnet::RobotContext& robot) override;
  void reset() override;

 private:
  void lead(swarmnet::RobotContext& robot);
  void follow(swarmnet::RobotContext& robot);

  swarmnet::RobotId leader_;
  double beacon_interval_s_;
  double follow_distance_m_;
  double speed_fraction_;
  double next_beacon_s_ = 0.0;
  std::optional<swarmnet::Vec2> leader_position_;
};

}  // namespace example::follow_the_leader
