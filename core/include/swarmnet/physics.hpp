// Physics plugins: advance robot bodies by one step and answer proximity queries.
#pragma once

#include <cstddef>
#include <span>

#include "swarmnet/arena.hpp"
#include "swarmnet/plugin.hpp"
#include "swarmnet/robot_body.hpp"

namespace swarmnet {

// Where a movable object (Arena::objects) is: centre and heading.
struct ObjectPose {
  Vec2 position = Vec2::Zero();  // m
  double heading_rad = 0.0;
};

class Physics : public Plugin {
 public:
  static constexpr PluginKind kKind = PluginKind::physics;

  // Called once, before the first step, with the bodies at their initial poses.
  virtual void setup(const Arena& arena, std::span<const RobotBody> bodies) = 0;

  // Moves every body by its wheel speeds for dt_s seconds and resolves collisions with walls,
  // obstacles and other robots. After it returns no two bodies overlap and no body leaves the
  // arena or enters an obstacle; an engine with soft contacts (ode) may leave an overlap of a
  // bounded depth, which it documents (docs/physics-ode.md: about closing speed x sub-step).
  virtual void step(double dt_s, std::span<RobotBody> bodies) = 0;

  // Proximity ring of `robot`: ray k points at heading + 2*pi*k/rays.size(); each entry receives
  // the distance in metres from the body's surface to the nearest wall, obstacle or robot along
  // that ray, or range_m when nothing is within range. Valid for the bodies as of the last
  // setup() or step().
  virtual void sense_proximity(std::span<const RobotBody> bodies, std::size_t robot, double range_m,
                               std::span<double> rays) const = 0;

  // Poses of the arena's movable objects, in the order of Arena::objects, as of the last setup()
  // or step(). An engine that does not move objects returns an empty span (the default); one
  // that accepts objects in setup() returns one pose per object.
  [[nodiscard]] virtual std::span<const ObjectPose> object_poses() const { return {}; }
};

}  // namespace swarmnet
