// The proximity ring, answered against the same geometry ODE collides: the arena's walls,
// the obstacles and the other robots' discs.
//
// Rays are cast analytically against the same shapes rather than as ODE ray geoms (one space query
// and one geom per ray, moved for every robot): other robots come from the SDK's uniform grid and
// only the rays within a neighbour's angular width are tested against it, so a ring costs
// O(rays + obstacles * rays + robots in range), as in kinematic2d.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/physics.hpp"
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
  // from the body's surface to the first wall, obstacle or other robot, or exactly range_m when
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
  mutable std::vector<Vec2> offsets_;     // ray directions at heading 0
  mutable std::vector<Vec2> directions_;  // turned by the current robot's heading
};

// Distances along unit direction `u` from `origin`; infinity for a miss.
double ray_to_walls(const Arena& arena, const Vec2& origin, const Vec2& u);
double ray_to_rect(const Rect& rect, const Vec2& origin, const Vec2& u);
double ray_to_disc(const Vec2& centre, double radius_m, const Vec2& origin, const Vec2& u);
double ray_to_object(const ArenaObject& shape, const ObjectPose& pose, const Vec2& origin,
                     const Vec2& u);

}  // namespace swarmnet::ode
