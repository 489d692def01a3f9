// `tether` controller (an out-of-tree example of the sensing SDK): robots spread out from where
// they start and stop before their radios lose the others, from what their own radios measure.
// It uses one-hop beacons, unicasts with send reports, the radio neighbour table and
// route_to().
#pragma once

#include <cstdint>

#include "swarmnet/controller.hpp"

namespace example::tether {

class Tether final : public swarmnet::Controller {
 public:
  static swarmnet::PluginInfo info();
  explicit Tether(const swarmnet::PluginArgs& args);

  void init(swarmnet::RobotContext& robot) override;
  void control_step(swarmnet::RobotContext& robot) override;
  void reset() override;

  // For tests: whether this robot has stopped for good.
  [[nodiscard]] bool stopped() const { return stopped_; }

 private:
  void beacon(swarmnet::RobotContext& robot);
  void check_in(swarmnet::RobotContext& robot);
  // Neighbours heard at rssi_floor_dbm or better (smoothed).
  [[nodiscard]] int strong_neighbors(const swarmnet::RobotContext& robot) const;

  swarmnet::RobotId anchor_;
  int min_neighbors_;
  int max_hops_;
  double rssi_floor_dbm_;
  double speed_fraction_;
  double beacon_interval_s_;
  double check_in_interval_s_;
  double grace_s_;
  swarmnet::Vec2 start_ = swarmnet::Vec2::Zero();
  double next_beacon_s_ = 0.0;
  double next_check_in_s_ = 0.0;
  bool stopped_ = false;
};

}  // namespace example::tether
