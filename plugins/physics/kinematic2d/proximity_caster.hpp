// The proximity ring: rays from a robot's centre against walls, obstacles and other robots.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/spatial_grid.hpp"

namespace swarmnet::kinematic2d {

class ProximityCaster {
 public:
  // Fills `rays` for robot `robot`: ray k leaves the centre at heading + 2*pi*k/rays.size() and
  // reads the distance from the body's surface to the first wall, obstacle (slab test) or other
  // robot's disc it meets, or exactly range_m when there is none within range_m. Other robots come
  // from `grid` (built from `bodies`' positions; `max_radius_m` bounds every radius), so the cost
  // is O(rays * (obstacles + robots within range)). Keeps scratch space: one caster must not be
  // used from two threads at once.
  void cast(const Arena& arena, const SpatialGrid& grid, double max_radius_m,
            std::span<const RobotBody> bodies, std::size_t robot, double range_m,
            std::span<double> rays) const;

 private:
  mutable std::vector<Vec2> offsets_;     // ray directions at heading 0
  mutable std::vector<Vec2> directions_;  // turned by the current robot's heading
};

}  // namespace swarmnet::kinematic2d
