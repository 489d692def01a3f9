#include "proximity_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace swarmnet::ode {

namespace {
constexpr double kMiss = std::numeric_limits<double>::infinity();
}  // namespace

double ray_to_walls(const Arena& arena, const Vec2& origin, const Vec2& u) {
  double t = kMiss;
  if (u.x() > 0.0) t = std::min(t, (arena.width_m - origin.x()) / u.x());
  if (u.x() < 0.0) t = std::min(t, -origin.x() / u.x());
  if (u.y() > 0.0) t = std::min(t, (arena.height_m - origin.y()) / u.y());
  if (u.y() < 0.0) t = std::min(t, -origin.y() / u.y());
  return std::max(t, 0.0);
}

double ray_to_rect(const Rect& rect, const Vec2& origin, const Vec2& u) {
  double enter = 0.0;
  double leave = kMiss;
  const double lows[2] = {rect.x_min_m, rect.y_min_m};
  const double highs[2] = {rect.x_max_m, rect.y_max_m};
  for (int axis = 0; axis < 2; ++axis) {
    const double o = origin[axis];
    const double d = u[axis];
    if (d == 0.0) {
      if (o < lows[axis] || o > highs[axis]) return kMiss;
      continue;
    }
    double t0 = (lows[axis] - o) / d;
    double t1 = (highs[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return kMiss;
  }
  return enter;
}

double ray_to_disc(const Vec2& centre, double radius_m, const Vec2& origin, const Vec2& u) {
  const Vec2 to_centre = centre - origin;
  const double along = u.dot(to_centre);
  const double excess = to_centre.squaredNorm() - radius_m * radius_m;
  if (excess <= 0.0) return 0.0;
  if (along <= 0.0) return kMiss;
  const double discriminant = along * along - excess;
  if (discriminant < 0.0) return kMiss;
  return along - std::sqrt(discriminant);
}

double ray_to_object(const ArenaObject& shape, const ObjectPose& pose, const Vec2& origin,
                     const Vec2& u) {
  if (shape.shape == ArenaObject::Shape::cylinder) {
    return ray_to_disc(pose.position, shape.radius_m, origin, u);
  }
  // The ray in the box's frame, against the box as an axis-aligned rectangle there.
  const double c = std::cos(pose.heading_rad);
  const double s = std::sin(pose.heading_rad);
  const Vec2 offset = origin - pose.position;
  const Vec2 local_origin(c * offset.x() + s * offset.y(), -s * offset.x() + c * offset.y());
  const Vec2 local_u(c * u.x() + s * u.y(), -s * u.x() + c * u.y());
  const Rect box{-0.5 * shape.size_x_m, -0.5 * shape.size_y_m, 0.5 * shape.size_x_m,
                 0.5 * shape.size_y_m};
  return ray_to_rect(box, local_origin, local_u);
}

void ProximitySensor::setup(const Arena& arena, std::span<const RobotBody> bodies,
                            std::span<const ObjectPose> objects, double cell_m) {
  arena_ = arena;
  max_radius_m_ = 0.0;
  for (const RobotBody& body : bodies) max_radius_m_ = std::max(max_radius_m_, body.radius_m);
  grid_.reset(Rect{0.0, 0.0, arena.width_m, arena.height_m}, cell_m);
  update(bodies, objects);
}

void ProximitySensor::update(std::span<const RobotBody> bodies,
                             std::span<const ObjectPose> objects) {
  object_poses_.assign(objects.begin(), objects.end());
  points_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) points_[i] = bodies[i].position;
  grid_.build(points_);
}

void ProximitySensor::sense(std::span<const RobotBody> bodies, std::size_t robot, double range_m,
                            std::span<double> rays) const {
  if (rays.empty()) return;
  const RobotBody& self = bodies[robot];
  const Vec2& origin = self.position;
  const double reach_m = self.radius_m + range_m;  // measured from the centre
  const double spacing_rad = 2.0 * std::numbers::pi / static_cast<double>(rays.size());
  // Ray k's direction is its body-frame unit vector turned by the heading: two trigonometric
  // calls per robot instead of two per ray.
  if (offsets_.size() != rays.size()) {
    offsets_.resize(rays.size());
    directions_.resize(rays.size());
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const double angle = spacing_rad * static_cast<double>(k);
      offsets_[k] = Vec2(std::cos(angle), std::sin(angle));
    }
  }
  const double c = std::cos(self.heading_rad);
  const double s = std::sin(self.heading_rad);
  for (std::size_t k = 0; k < rays.size(); ++k) {
    const Vec2& o = offsets_[k];
    directions_[k] = Vec2(c * o.x() - s * o.y(), s * o.x() + c * o.y());
    rays[k] = std::min(ray_to_walls(arena_, origin, directions_[k]), reach_m);
  }
  for (const Rect& obstacle : arena_.obstacles) {
    const Vec2 nearest(std::clamp(origin.x(), obstacle.x_min_m, obstacle.x_max_m),
                       std::clamp(origin.y(), obstacle.y_min_m, obstacle.y_max_m));
    if ((origin - nearest).norm() > reach_m) continue;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      rays[k] = std::min(rays[k], ray_to_rect(obstacle, origin, directions_[k]));
    }
  }
  for (std::size_t o = 0; o < object_poses_.size(); ++o) {
    const ArenaObject& shape = arena_.objects[o];
    const ObjectPose& pose = object_poses_[o];
    // The radius of the disc around the centre that holds the object, whatever its heading.
    const double reach_of_object_m = shape.shape == ArenaObject::Shape::box
                                         ? std::hypot(0.5 * shape.size_x_m, 0.5 * shape.size_y_m)
                                         : shape.radius_m;
    if ((pose.position - origin).norm() > reach_m + reach_of_object_m) continue;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      rays[k] = std::min(rays[k], ray_to_object(shape, pose, origin, directions_[k]));
    }
  }
  const auto ray_count = static_cast<std::int64_t>(rays.size());
  grid_.for_each_candidate(origin, reach_m + max_radius_m_, [&](std::uint32_t j) {
    if (j == robot) return;
    const RobotBody& other = bodies[j];
    const Vec2 offset = other.position - origin;
    const double distance_m = offset.norm();
    if (distance_m > reach_m + other.radius_m) return;
    // Only the rays within the disc's angular half-width of its bearing can meet it.
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
  for (double& ray : rays) {
    ray = ray >= reach_m ? range_m : std::clamp(ray - self.radius_m, 0.0, range_m);
  }
}

}  // namespace swarmnet::ode
