// The ODE world of one engine instance: the library's initialisation, the world and its solver
// settings, the collision space, the joint group of the current sub-step's contacts, and the
// static geometry (walls, obstacles).
//
// Everything lies in the plane z = 0: robots are spheres of their radius centred on it, so that
// every contact between two robots is the contact of their discs; walls and obstacles are boxes
// standing on it, taller than any robot. Gravity is off: the floor is not simulated as a body,
// its normal force (mass * gravity) enters only the friction limits of the drive (robot_drive.hpp).
#pragma once

#include <ode/ode.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "contact_model.hpp"
#include "ode_parameters.hpp"
#include "swarmnet/arena.hpp"

namespace swarmnet::ode {

// dInitODE2 / dCloseODE, counted, so that several engines (or tests) can live in one process.
class OdeLibrary {
 public:
  OdeLibrary();
  OdeLibrary(const OdeLibrary&) = delete;
  OdeLibrary& operator=(const OdeLibrary&) = delete;
  ~OdeLibrary();
};

class OdeWorld {
 public:
  // A world over `arena` for bodies whose radius is about `typical_radius_m` (sizes the
  // collision space's blocks). Add the arena's walls and obstacles with add_static_geometry().
  OdeWorld(const OdeParameters& parameters, const Arena& arena, double typical_radius_m);
  OdeWorld(const OdeWorld&) = delete;
  OdeWorld& operator=(const OdeWorld&) = delete;
  ~OdeWorld();

  // Four walls enclosing [0, width] x [0, height], each `wall_thickness_m` thick outside it, and
  // one box per obstacle rectangle.
  void add_static_geometry(const Arena& arena);

  // One sub-step of h seconds, in two halves. collide(): finds contacts in the space (geoms in
  // insertion order) and adds a contact joint for each, flagging in `touching` the robots that
  // got one. advance(): advances the world with QuickStep and drops the contact joints.
  void collide(std::vector<std::uint8_t>* touching);
  void advance(double h_s);

  [[nodiscard]] dWorldID world() const { return world_; }
  [[nodiscard]] dSpaceID space() const { return space_; }
  // Joints that live for one sub-step (contacts, and motors of robots in contact): emptied by
  // advance().
  [[nodiscard]] dJointGroupID substep_joints() const { return contact_group_; }
  // Contacts created in the last step(), for tests and diagnostics.
  [[nodiscard]] std::size_t last_contact_count() const { return contacts_.last_count(); }

  static constexpr double kWallThicknessM = 1.0;
  static constexpr double kStaticHeightM = 1.0;  // walls and obstacles, centred on z = 0

 private:
  void add_static_box(double x_min, double y_min, double x_max, double y_max);

  OdeLibrary library_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contact_group_ = nullptr;
  ContactModel contacts_;
};

}  // namespace swarmnet::ode
