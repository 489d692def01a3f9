#include "proximity_sensor.hpp"

#include <algorithm>
#include <cmath>

namespace swarmnet::ode {

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
  ring_.cast(arena_, grid_, max_radius_m_, bodies, robot, range_m, rays, object_poses_);
}

}  // namespace swarmnet::ode
