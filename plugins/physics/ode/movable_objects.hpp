// The arena's movable objects (Arena::objects) as ODE bodies that robots push.
//
// A box is an ODE box as tall as kObjectHeightM, centred on the plane z = 0 like the robots'
// spheres, so that a robot touches its vertical faces; an upright cylinder collides, like a
// robot, as a sphere of its radius: its disc in the plane. Inertia is the solid shape's (box or
// cylinder of that height).
//
// Floor friction: the object rests on the floor with normal force mass * gravity. A linear motor
// with target velocity 0 along world x and y, each axis bounded by object_floor_friction * mass *
// gravity, and an angular motor with target 0 about z, bounded by that force times (2/3) * r (the
// spinning friction of a uniformly loaded disc of radius r; a box counts as the disc of its
// area), are solved with the contacts: Coulomb friction, static and sliding, as ODE's contact
// friction models it (a friction box rather than a circle). Sliding and spinning are bounded
// separately (their coupling, which lowers both when an object slides and spins at once, is not
// modelled). A robot moves an object only while it pushes harder than the object's floor
// friction, and an object held by a wall or too heavy does not move at all.
#pragma once

#include <ode/ode.h>

#include <span>
#include <vector>

#include "ode_parameters.hpp"
#include "swarmnet/arena.hpp"
#include "swarmnet/physics.hpp"

namespace swarmnet::ode {

class MovableObjects {
 public:
  void create(dWorldID world, dSpaceID space, std::span<const ArenaObject> objects,
              const OdeParameters& parameters);

  // Returns the bodies to the plane and records their poses.
  void read_poses();

  [[nodiscard]] std::span<const ObjectPose> poses() const { return poses_; }
  // Fastest object speed in the plane, m/s.
  [[nodiscard]] double fastest_mps() const;
  // Half the smallest extent of any object (box side or cylinder diameter), m; 0 when none.
  [[nodiscard]] double smallest_half_extent_m() const { return smallest_half_extent_m_; }

  static constexpr double kObjectHeightM = 0.2;

 private:
  struct Body {
    dBodyID body = nullptr;
  };
  std::vector<Body> bodies_;
  std::vector<ObjectPose> poses_;
  double smallest_half_extent_m_ = 0.0;
};

}  // namespace swarmnet::ode
