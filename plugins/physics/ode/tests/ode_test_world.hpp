// Small worlds for the ode plugin's tests: the plugin built as the kernel would build it, robots
// placed by hand or at random without overlap.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "ode_physics.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/testing.hpp"

namespace swarmnet::ode::testing {

inline RobotBody robot_at(double x, double y, double heading_rad = 0.0,
                          double max_speed_mps = 5.0) {
  RobotBody body;
  body.position = Vec2(x, y);
  body.heading_rad = heading_rad;
  body.max_speed_mps = max_speed_mps;
  return body;
}

inline std::unique_ptr<OdePhysics> make_physics(
    const Arena& arena, const std::vector<RobotBody>& bodies,
    const swarmnet::testing::ParamOverrides& params = {}) {
  auto physics = std::make_unique<OdePhysics>(swarmnet::testing::plugin_args<OdePhysics>(params));
  physics->setup(arena, bodies);
  return physics;
}

inline Arena open_arena(double width_m, double height_m) {
  Arena arena;
  arena.width_m = width_m;
  arena.height_m = height_m;
  return arena;
}

// `count` robots at uniform random positions in the arena, none touching another or a wall.
inline std::vector<RobotBody> random_robots(const Arena& arena, std::size_t count,
                                            std::uint64_t seed) {
  RandomStream random(seed);
  std::vector<RobotBody> bodies;
  while (bodies.size() < count) {
    RobotBody body = robot_at(0.0, 0.0, random.uniform(-3.14159, 3.14159), 1.0);
    const double r = body.radius_m;
    body.position =
        Vec2(random.uniform(r, arena.width_m - r), random.uniform(r, arena.height_m - r));
    bool free = true;
    for (const RobotBody& other : bodies) {
      free = free && (other.position - body.position).norm() >= other.radius_m + r;
    }
    if (free) bodies.push_back(body);
  }
  return bodies;
}

// The largest overlap of two robots' discs, m (0 when none overlap).
inline double deepest_penetration(const std::vector<RobotBody>& bodies) {
  double deepest = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      const double gap = (bodies[i].position - bodies[j].position).norm() - bodies[i].radius_m -
                         bodies[j].radius_m;
      deepest = std::max(deepest, -gap);
    }
  }
  return deepest;
}

}  // namespace swarmnet::ode::testing
