// diffusion: the reference study's mobility. Drive straight, turn away from what is ahead,
// and now and then turn to a fresh random heading.
#pragma once

#include <cstdint>
#include <vector>

#include "swarmnet/controller.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet::diffusion {

class Diffusion final : public Controller {
 public:
  static PluginInfo info();
  explicit Diffusion(const PluginArgs& args);

  void init(RobotContext& robot) override;
  void control_step(RobotContext& robot) override;
  void reset() override;

 private:
  enum class Mode : std::uint8_t { driving, avoiding, random_turn };

  // Everything that changes while running, so that reset() can restore the post-init copy.
  struct State {
    RandomStream random;
    Mode mode = Mode::driving;
    double turn_sign = 1.0;  // +1: counter-clockwise (left), -1: clockwise (right)
    double target_heading_rad = 0.0;
    double next_random_turn_s = 0.0;
  };

  // Whether the front sector sees something closer than avoid_distance_m; if so, also which side
  // to turn to (+1 left, -1 right, 0 when both sides read the same).
  struct FrontView {
    bool blocked = false;
    double away_sign = 0.0;
  };
  [[nodiscard]] FrontView look_ahead(const RobotContext& robot) const;
  void schedule_random_turn(double now_s);
  void turn(RobotContext& robot) const;

  double speed_mps_;
  double turn_speed_mps_;
  double avoid_distance_m_;
  double front_half_angle_rad_;
  double turn_interval_s_;
  // Per proximity ray: +1 front-left, -1 front-right, 0 straight ahead, NaN outside the front
  // sector. Computed in init() from the ring's size.
  std::vector<double> ray_sides_;
  State state_;
  State initial_;
};

}  // namespace swarmnet::diffusion
