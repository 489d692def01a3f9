// The proximity ring as a physics plugin answers it (Physics::sense_proximity): rays from a
// robot's centre against the arena's walls, its obstacles, its movable objects and the other
// robots' discs, cast analytically. Both in-tree physics engines use it, so a ring reads the same
// on either; the kernel's range-and-bearing device casts its lines of sight with the same rays.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/physics.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/spatial_grid.hpp"

namespace swarmnet {

// Distances along the unit direction `u` from `origin`; kRayMiss when the ray misses.
inline constexpr double kRayMiss = std::numeric_limits<double>::infinity();

// To the wall the ray leaves the arena by (`origin` inside it).
inline double ray_to_walls(const Arena& arena, const Vec2& origin, const Vec2& u) {
  double t = kRayMiss;
  if (u.x() > 0.0) t = std::min(t, (arena.width_m - origin.x()) / u.x());
  if (u.x() < 0.0) t = std::min(t, -origin.x() / u.x());
  if (u.y() > 0.0) t = std::min(t, (arena.height_m - origin.y()) / u.y());
  if (u.y() < 0.0) t = std::min(t, -origin.y() / u.y());
  return std::max(t, 0.0);
}

// Slab test: to where the ray enters `rect`; 0 from inside it.
inline double ray_to_rect(const Rect& rect, const Vec2& origin, const Vec2& u) {
  double enter = 0.0;
  double leave = kRayMiss;
  const double lows[2] = {rect.x_min_m, rect.y_min_m};
  const double highs[2] = {rect.x_max_m, rect.y_max_m};
  for (int axis = 0; axis < 2; ++axis) {
    const double o = origin[axis];
    const double d = u[axis];
    if (d == 0.0) {
      if (o < lows[axis] || o > highs[axis]) return kRayMiss;
      continue;
    }
    double t0 = (lows[axis] - o) / d;
    double t1 = (highs[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return kRayMiss;
  }
  return enter;
}

// To where the ray enters the disc (centre, radius); 0 from on or inside it.
inline double ray_to_disc(const Vec2& centre, double radius_m, const Vec2& origin, const Vec2& u) {
  const Vec2 to_centre = centre - origin;
  const double along = u.dot(to_centre);
  const double excess = to_centre.squaredNorm() - radius_m * radius_m;
  if (excess <= 0.0) return 0.0;
  if (along <= 0.0) return kRayMiss;  // the disc is behind
  const double discriminant = along * along - excess;
  if (discriminant < 0.0) return kRayMiss;
  return along - std::sqrt(discriminant);
}

// To a movable object at `pose`: a cylinder's disc, or the box seen in its own frame.
inline double ray_to_object(const ArenaObject& shape, const ObjectPose& pose, const Vec2& origin,
                            const Vec2& u) {
  if (shape.shape == ArenaObject::Shape::cylinder) {
    return ray_to_disc(pose.position, shape.radius_m, origin, u);
  }
  const Vec2 local_origin = in_frame(origin, pose.position, pose.heading_rad);
  const Vec2 local_u = in_frame(u, Vec2::Zero(), pose.heading_rad);
  const Rect box{-0.5 * shape.size_x_m, -0.5 * shape.size_y_m, 0.5 * shape.size_x_m,
                 0.5 * shape.size_y_m};
  return ray_to_rect(box, local_origin, local_u);
}

// From `point` to the nearest point of `rect` (0 inside it).
inline double distance_to_rect(const Rect& rect, const Vec2& point) {
  const Vec2 nearest(std::clamp(point.x(), rect.x_min_m, rect.x_max_m),
                     std::clamp(point.y(), rect.y_min_m, rect.y_max_m));
  return (point - nearest).norm();
}

// The radius of the disc around a movable object's centre that holds it, whatever its heading.
inline double object_reach_m(const ArenaObject& shape) {
  return shape.shape == ArenaObject::Shape::box
             ? std::hypot(0.5 * shape.size_x_m, 0.5 * shape.size_y_m)
             : shape.radius_m;
}

class ProximityRing {
 public:
  // Fills `rays` for robot `robot`: ray k leaves the centre at heading + 2*pi*k/rays.size() and
  // reads the distance from the body's surface to the first wall, obstacle, movable object
  // (`object_poses[i]` is arena.objects[i]'s pose) or other robot's disc it meets, or exactly
  // range_m when there is none within range_m (0 when the robot already touches it). Other robots
  // come from `grid` (built from `bodies`' positions; `max_radius_m` bounds every radius), and
  // only the rays within a neighbour's angular width are tested against it, so the cost is
  // O(rays * (obstacles + objects) + robots within range). Keeps scratch space: one ring must
  // not be used from two threads at once.
  void cast(const Arena& arena, const SpatialGrid& grid, double max_radius_m,
            std::span<const RobotBody> bodies, std::size_t robot, double range_m,
            std::span<double> rays, std::span<const ObjectPose> object_poses = {}) const {
    if (rays.empty()) return;
    const RobotBody& self = bodies[robot];
    const Vec2& origin = self.position;
    const double reach_m = self.radius_m + range_m;  // from the centre here, the surface on output
    const double spacing_rad = 2.0 * std::numbers::pi / static_cast<double>(rays.size());
    turn_directions(rays.size(), spacing_rad, self.heading_rad);
    for (std::size_t k = 0; k < rays.size(); ++k) {
      rays[k] = std::min(ray_to_walls(arena, origin, directions_[k]), reach_m);
    }
    for (const Rect& obstacle : arena.obstacles) {
      if (distance_to_rect(obstacle, origin) > reach_m) continue;
      for (std::size_t k = 0; k < rays.size(); ++k) {
        rays[k] = std::min(rays[k], ray_to_rect(obstacle, origin, directions_[k]));
      }
    }
    for (std::size_t o = 0; o < object_poses.size() && o < arena.objects.size(); ++o) {
      const ArenaObject& shape = arena.objects[o];
      if ((object_poses[o].position - origin).norm() > reach_m + object_reach_m(shape)) continue;
      for (std::size_t k = 0; k < rays.size(); ++k) {
        rays[k] = std::min(rays[k], ray_to_object(shape, object_poses[o], origin, directions_[k]));
      }
    }
    cast_at_robots(grid, max_radius_m, bodies, robot, reach_m, spacing_rad, rays);
    for (double& ray : rays) {
      // Nothing within range reads exactly range_m (reach_m - radius may round differently).
      ray = ray >= reach_m ? range_m : std::clamp(ray - self.radius_m, 0.0, range_m);
    }
  }

 private:
  // Ray k's direction: its body-frame unit vector turned by the heading (two trigonometric calls
  // per robot instead of two per ray).
  void turn_directions(std::size_t count, double spacing_rad, double heading_rad) const {
    if (offsets_.size() != count) {
      offsets_.resize(count);
      directions_.resize(count);
      for (std::size_t k = 0; k < count; ++k) {
        const double angle = spacing_rad * static_cast<double>(k);
        offsets_[k] = Vec2(std::cos(angle), std::sin(angle));
      }
    }
    const double c = std::cos(heading_rad);
    const double s = std::sin(heading_rad);
    for (std::size_t k = 0; k < count; ++k) {
      const Vec2& o = offsets_[k];
      directions_[k] = Vec2(c * o.x() - s * o.y(), s * o.x() + c * o.y());
    }
  }

  void cast_at_robots(const SpatialGrid& grid, double max_radius_m,
                      std::span<const RobotBody> bodies, std::size_t robot, double reach_m,
                      double spacing_rad, std::span<double> rays) const {
    const RobotBody& self = bodies[robot];
    const Vec2& origin = self.position;
    const auto ray_count = static_cast<std::int64_t>(rays.size());
    grid.for_each_candidate(origin, reach_m + max_radius_m, [&](std::uint32_t j) {
      if (j == robot) return;
      const RobotBody& other = bodies[j];
      const Vec2 offset = other.position - origin;
      const double distance_m = offset.norm();
      if (distance_m > reach_m + other.radius_m) return;
      // Only rays within the disc's angular half-width of its bearing can meet it: in a dense
      // swarm that is 1 to 3 rays per neighbour instead of all of them. The margin keeps a ray
      // that grazes the disc in the test; ray_to_disc() decides.
      std::int64_t first = 0;
      std::int64_t last = ray_count - 1;
      if (distance_m > other.radius_m) {
        const double half_width_rad = std::asin(other.radius_m / distance_m) + 1e-9;
        const double bearing_rad = std::atan2(offset.y(), offset.x()) - self.heading_rad;
        first = static_cast<std::int64_t>(std::ceil((bearing_rad - half_width_rad) / spacing_rad));
        last = static_cast<std::int64_t>(std::floor((bearing_rad + half_width_rad) / spacing_rad));
        if (last - first + 1 >= ray_count) {
          first = 0;
          last = ray_count - 1;
        }
      }
      for (std::int64_t k = first; k <= last; ++k) {
        const auto index = static_cast<std::size_t>(((k % ray_count) + ray_count) % ray_count);
        rays[index] = std::min(
            rays[index], ray_to_disc(other.position, other.radius_m, origin, directions_[index]));
      }
    });
  }

  mutable std::vector<Vec2> offsets_;     // ray directions at heading 0
  mutable std::vector<Vec2> directions_;  // turned by the current robot's heading
};

}  // namespace swarmnet
