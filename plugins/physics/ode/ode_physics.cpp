#include "ode_physics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swarmnet::ode {

PluginInfo OdePhysics::info() {
  return PluginInfo{
      "ode", "1.0.0",
      "Rigid-body dynamics in ODE: mass, inertia, wheel friction, pushing, soft contacts.",
      "Each robot is a rigid body in the Open Dynamics Engine (ODE 0.16, double precision): a "
      "uniform solid cylinder of robot_mass_kg and the robot's radius, moving in the plane, "
      "colliding as the disc of its radius. Walls and obstacles are static boxes.\n"
      "Drive: the wheels are modelled by what their friction with the floor does, not as hinged "
      "bodies: a velocity servo along the heading (target (left + right) / 2) and across it "
      "(target 0), each limited to wheel_friction * mass * gravity, and about the vertical "
      "(target (right - left) / axle) limited to that force times axle / 2. A robot so "
      "accelerates at most at wheel_friction * gravity, carries momentum, pushes other robots "
      "with at most its traction and slips when pushed harder. The servo is a pair of ODE "
      "velocity motors (linear, two body axes; angular) solved with the contacts, so static "
      "friction holds exactly; with drive: motor_joint_in_contact (default) they are enabled "
      "only for a robot that touches something in the sub-step, and a free robot gets their "
      "exact solution as a force instead, without solver rows. Hinged wheels would give the "
      "same limits at five times the constraint rows and with stiff wheel-floor contacts.\n"
      "Contacts: ODE's quad-tree space finds touching pairs in time linear in the number of "
      "bodies; "
      "each contact point becomes a contact joint with Coulomb friction contact_friction in the "
      "plane and softness contact_erp / contact_cfm_m_per_n; contacts are made planar (point on "
      "the plane, normal in it), so bodies never tilt. Contacts are soft and exist only once "
      "bodies overlap: two bodies closing at u m/s may overlap by up to u times a sub-step (plus "
      "contact_surface_layer_m) before the contact separates them, about 1 cm at 1 m/s and the "
      "default 10 ms; kinematic2d forbids any overlap.\n"
      "Stepping: a step of step_s is cut into equal sub-steps, at least ceil(step_s / "
      "max_substep_s) and enough that no body moves more than max_travel_fraction of the smallest "
      "robot radius per sub-step at the larger of its speed and its fastest commanded wheel speed; "
      "each sub-step collides, then advances the world with QuickStep (solver_iterations). No "
      "body can tunnel through a wall, an obstacle or another robot. Single-threaded; bodies and "
      "geoms are created in robot order and ODE's solver generator is re-seeded every sub-step, "
      "so a scenario and seed give identical results.\n"
      "Movable objects (arena.objects): boxes and upright cylinders with their mass, pushed by "
      "robots through the same contacts; on the floor each resists sliding with at most "
      "object_floor_friction * mass * gravity and spinning with that force times 2/3 of its "
      "(equal-area) radius. Their poses are written to objects.csv in the run directory.\n"
      "Proximity: rays are cast analytically against the walls, the obstacles, the movable "
      "objects and the other robots' discs (from a uniform grid), as in kinematic2d.",
      OdeParameters::schema()};
}

OdePhysics::OdePhysics(const PluginArgs& args) : parameters_(OdeParameters::from(args.params)) {}

void OdePhysics::setup(const Arena& arena, std::span<const RobotBody> bodies) {
  double max_radius_m = 0.0;
  min_radius_m_ = bodies.empty() ? 0.0 : bodies.front().radius_m;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RobotBody& body = bodies[i];
    const std::string robot = "ode: robot " + std::to_string(i);
    if (!(body.radius_m > 0.0) || !(body.axle_m > 0.0)) {
      throw std::invalid_argument(robot + ": radius and axle must be positive");
    }
    const Vec2& p = body.position;
    if (p.x() < body.radius_m || p.x() > arena.width_m - body.radius_m || p.y() < body.radius_m ||
        p.y() > arena.height_m - body.radius_m) {
      throw std::invalid_argument(robot + " at (" + std::to_string(p.x()) + ", " +
                                  std::to_string(p.y()) + ") m is not inside the arena");
    }
    max_radius_m = std::max(max_radius_m, body.radius_m);
    min_radius_m_ = std::min(min_radius_m_, body.radius_m);
  }
  world_ = std::make_unique<OdeWorld>(parameters_, arena, bodies.empty() ? 0.085 : max_radius_m);
  world_->add_static_geometry(arena);
  drives_.assign(bodies.size(), RobotDrive{});
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    drives_[i].create(world_->world(), world_->space(), bodies[i], i, parameters_);
  }
  touching_.assign(bodies.size(), 0);
  objects_.create(world_->world(), world_->space(), arena.objects, parameters_);
  const double area_m2 = arena.width_m * arena.height_m;
  const double robots = static_cast<double>(std::max<std::size_t>(bodies.size(), 1));
  proximity_.setup(arena, bodies, objects_.poses(),
                   std::max(2.0 * max_radius_m, std::sqrt(area_m2 / (4.0 * robots))));
  last_substeps_ = 0;
}

int OdePhysics::substeps_for(double dt_s, std::span<const RobotBody> bodies) const {
  double fastest_mps = objects_.fastest_mps();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RobotBody& body = bodies[i];
    fastest_mps = std::max(
        {fastest_mps, std::abs(body.left_mps), std::abs(body.right_mps), drives_[i].speed_mps()});
  }
  double substeps = std::ceil(dt_s / parameters_.max_substep_s);
  double smallest_m = min_radius_m_;
  if (objects_.smallest_half_extent_m() > 0.0) {
    smallest_m = smallest_m > 0.0 ? std::min(smallest_m, objects_.smallest_half_extent_m())
                                  : objects_.smallest_half_extent_m();
  }
  if (smallest_m > 0.0) {
    const double travel_m = parameters_.max_travel_fraction * smallest_m;
    substeps = std::max(substeps, std::ceil(fastest_mps * dt_s / travel_m));
  }
  if (!(substeps <= kMaxSubsteps)) return kMaxSubsteps;
  return std::max(1, static_cast<int>(substeps));
}

void OdePhysics::step(double dt_s, std::span<RobotBody> bodies) {
  const int substeps = substeps_for(dt_s, bodies);
  const double h_s = dt_s / substeps;
  for (std::size_t i = 0; i < bodies.size(); ++i) drives_[i].command(bodies[i]);
  for (int s = 0; s < substeps; ++s) {
    world_->collide(&touching_);
    for (std::size_t i = 0; i < drives_.size(); ++i) {
      drives_[i].prepare(h_s, touching_[i] != 0, world_->world(), world_->substep_joints());
    }
    world_->advance(h_s);
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    drives_[i].flatten();
    drives_[i].read_pose(bodies[i]);
  }
  objects_.read_poses();
  proximity_.update(bodies, objects_.poses());
  last_substeps_ = substeps;
}

void OdePhysics::sense_proximity(std::span<const RobotBody> bodies, std::size_t robot,
                                 double range_m, std::span<double> rays) const {
  proximity_.sense(bodies, robot, range_m, rays);
}

Vec2 OdePhysics::velocity(std::size_t robot) const {
  const dReal* v = dBodyGetLinearVel(drives_[robot].body());
  return {v[0], v[1]};
}

}  // namespace swarmnet::ode

SWARMNET_PLUGIN(swarmnet::ode::OdePhysics)
