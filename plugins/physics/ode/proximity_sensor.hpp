// The proximity ring, answered against the same geometry ODE collides: the arena's walls, the
// obstacles, the movable objects and the other robots' discs.
//
// Rays are cast analytically against the same shapes (the SDK's ProximityRing, as kinematic2d
// does) rather than as ODE ray geoms (one space query and one geom per ray, moved for every
// robot).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/physics.hpp"
#include "swarmnet/proximity_ring.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/spatial_grid.hpp"

namespace swarmnet::ode {

class ProximitySensor {
 public:
  // `objects` are the poses of arena.objects (whose shapes and sizes the arena gives).
  void setup(const Arena& arena, std::span<const RobotBody> bodies,
             std::span<const ObjectPose> objects, double cell_m);

  // Re-indexes the robots' positions and takes the objects' poses; call after every move.
  void update(std::span<const RobotBody> bodies, std::span<const ObjectPose> objects);

  // Ray k leaves the centre of `robot` at heading + 2*pi*k/rays.size(); it reads the distance
  // from the body's surface to the first wall, obstacle, movable object or other robot, or
  // exactly range_m when
  // there is none within range_m (0 when the robot already touches or overlaps it). Movable
  // objects are tested one by one (a scenario has a handful), the others from the grid.
  void sense(std::span<const RobotBody> bodies, std::size_t robot, double range_m,
             std::span<double> rays) const;

 private:
  Arena arena_;
  double max_radius_m_ = 0.0;
  SpatialGrid grid_;
  std::vector<Vec2> points_;
  std::vector<ObjectPose> object_poses_;
  ProximityRing ring_;
};

}  // namespace swarmnet::ode
