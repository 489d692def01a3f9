// kinematic2d: differential-drive discs in a walled plane, kinematics plus collision projection.
#pragma once

#include <cstddef>
#include <span>

#include "collision_resolver.hpp"
#include "swarmnet/physics.hpp"
#include "swarmnet/proximity_ring.hpp"

namespace swarmnet::kinematic2d {

class Kinematic2d final : public Physics {
 public:
  static PluginInfo info();
  explicit Kinematic2d(const PluginArgs& args);

  void setup(const Arena& arena, std::span<const RobotBody> bodies) override;
  void step(double dt_s, std::span<RobotBody> bodies) override;
  void sense_proximity(std::span<const RobotBody> bodies, std::size_t robot, double range_m,
                       std::span<double> rays) const override;

 private:
  int collision_iterations_;
  Arena arena_;
  CollisionResolver resolver_;
  ProximityRing proximity_;
};

}  // namespace swarmnet::kinematic2d
