#include "kinematic2d.hpp"

#include <stdexcept>
#include <string>

#include "drive_kinematics.hpp"

namespace swarmnet::kinematic2d {

PluginInfo Kinematic2d::info() {
  return PluginInfo{
      "kinematic2d",
      "1.0.0",
      "Differential-drive discs: exact arc kinematics, projection-based collision resolution.",
      "Each robot is a disc of its radius driven by two wheels an axle length apart. Over a step "
      "the wheel speeds are constant, so the centre moves along the exact circular arc (a straight "
      "line for equal speeds): no integration error, whatever the step. Dynamics (mass, "
      "acceleration, friction, wheel slip) are not modelled: a robot moves exactly as its wheels "
      "command unless it collides.\n"
      "Collisions are resolved by projection, not by forces: overlapping robots are pushed apart "
      "along the line between their centres, half each, and robots are pushed out of obstacles "
      "(axis-aligned rectangles) and back inside the walls. This repeats up to "
      "collision_iterations times per step. Robots still in violation after that return to their "
      "position before the step (keeping their new heading), as does any robot that then overlaps "
      "one of them, so after every step no two robots overlap and no robot is outside the arena or "
      "inside an obstacle. A robot blocked by a wall therefore slides along it; a robot in a jam "
      "stays where it was. Touching is allowed; bodies are left 1 nm apart after a push.\n"
      "Robot pairs come from a uniform grid (cells at least one robot diameter wide, about 4 cells "
      "per robot), so a step costs O(N) for a swarm spread over the arena; pairs are visited in "
      "ascending index order, so runs are deterministic.\n"
      "Proximity: each ray is intersected with the walls, obstacles (slab test) and the discs of "
      "robots within range (from the grid); the reading is the distance from the body's surface to "
      "the first hit, or the range when there is none.\n"
      "Movable objects (arena.objects) are refused: kinematics cannot push them.",
      {integer_param("collision_iterations", 4, "",
                     "projection passes per step before robots still in violation are returned "
                     "to their previous position",
                     0, 64)}};
}

Kinematic2d::Kinematic2d(const PluginArgs& args)
    : collision_iterations_(static_cast<int>(args.params.integer("collision_iterations"))) {}

void Kinematic2d::setup(const Arena& arena, std::span<const RobotBody> bodies) {
  // Kinematics cannot push anything: an object would have to be a static obstacle, which is not
  // what the scenario says. Refused rather than silently frozen.
  if (!arena.objects.empty()) {
    throw std::invalid_argument(
        "kinematic2d: the arena has " + std::to_string(arena.objects.size()) +
        " movable object(s) (arena.objects), which kinematic2d cannot move; use a physics "
        "engine with dynamics (physics.plugin: ode) or remove arena.objects");
  }
  arena_ = arena;
  resolver_.setup(arena_, bodies, collision_iterations_);
}

void Kinematic2d::step(double dt_s, std::span<RobotBody> bodies) {
  resolver_.remember(bodies);
  for (RobotBody& body : bodies) integrate_drive(body, dt_s);
  resolver_.resolve(bodies);
}

void Kinematic2d::sense_proximity(std::span<const RobotBody> bodies, std::size_t robot,
                                  double range_m, std::span<double> rays) const {
  proximity_.cast(arena_, resolver_.grid(), resolver_.max_radius_m(), bodies, robot, range_m, rays);
}

}  // namespace swarmnet::kinematic2d

SWARMNET_PLUGIN(swarmnet::kinematic2d::Kinematic2d)
