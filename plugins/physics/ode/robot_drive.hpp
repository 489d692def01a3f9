// A robot as a rigid body driven by its two wheels.
//
// Drive model: the wheels are not bodies. A differential drive on a floor acts on the chassis
// only through the friction of its two contact patches, so the wheels are replaced by what that
// friction does: a velocity servo that drives the body towards the wheels' motion with a force
// bounded by Coulomb's law, as ODE's own contact friction would:
//   - along the heading, target (left + right) / 2, and across it, target 0 (wheels do not slide
//     sideways), each with force at most wheel_friction * mass * gravity: the Coulomb limit of
//     the floor under the robot;
//   - about the vertical, target (right - left) / axle, with torque at most
//     wheel_friction * mass * gravity * axle / 2 (each wheel pushes with half the normal force,
//     half an axle from the centre).
// The robot accelerates at most at wheel_friction * gravity, keeps its momentum against a push
// up to the friction limit and slips beyond it. Hinged wheel bodies would model the same limits
// through contacts with a floor, at three bodies and about sixteen constraint rows per robot (two
// hinges of five rows, two wheel contacts of three), with stiff wheel-floor contacts that need
// short sub-steps. ARGoS's dynamics2d engine drives its foot-bot the same way: a velocity-
// controlled constraint with a bounded force.
//
// Three implementations (parameter `drive`):
//   - "motor_joint": an ODE linear motor (two body-frame axes) and angular motor with these
//     targets and limits, solved together with the contacts by QuickStep: a pushed robot holds
//     exactly as long as its friction allows (static friction), a pushing one keeps its speed.
//   - "servo_force": before every sub-step, the force (and torque) that would bring the body to
//     its target velocity within the sub-step, clipped to the friction limit, is applied to the
//     body. No constraint rows, but computed from the velocity before the sub-step: in a contact
//     a pushed robot creeps and a pushing one droops.
//   - "motor_joint_in_contact" (default): the motors exist only for a robot that touches
//     something in the sub-step (contacts are found before the solver runs; the motors are
//     created with the contact joints and dropped with them); a robot that touches nothing gets
//     the force instead. For a lone body the motors' bounded velocity problem is
//     solved exactly by that force (the axes are orthogonal and the mass isotropic in the plane),
//     so the motion is that of motor_joint, while a free robot adds no rows to the solver: about
//     five times faster than motor_joint in a diffusing swarm.
//
// The body is a uniform solid cylinder of the robot's radius (for its inertia) and collides as a
// sphere of that radius centred on z = 0: in the plane, the disc of the robot.
#pragma once

#include <ode/ode.h>

#include <cstddef>

#include "ode_parameters.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet::ode {

class RobotDrive {
 public:
  // Creates the body, its geom in `space` and, unless the drive is servo_force, its motors, at
  // `body`'s pose, at rest. `index` is stored as the body's data (index + 1) so that contacts
  // can tell which robot they touch.
  void create(dWorldID world, dSpaceID space, const RobotBody& body, std::size_t index,
              const OdeParameters& parameters);

  // Sets the servo's targets from the wheel speeds in `body` (left_mps, right_mps, axle_m).
  void command(const RobotBody& body);

  // Before a sub-step of h_s seconds, after the collision pass: uses the motors when the drive
  // says so for a robot `in_contact` (or always), otherwise applies the bounded force and torque
  // towards the targets (ODE clears accumulated forces after each step).
  // motor_joint_in_contact creates the motors in `group` for this sub-step (the caller empties
  // it after the step): a free robot then has no joint at all, which keeps ODE's per-step island
  // building short.
  void prepare(double h_s, bool in_contact, dWorldID world, dJointGroupID group);

  // Writes the pose back: position on the plane, heading in [-pi, pi].
  void read_pose(RobotBody& body) const;

  // Speed of the centre in the plane, m/s.
  [[nodiscard]] double speed_mps() const;

  // Returns the body exactly to the plane: z, its vertical velocity, roll and pitch to zero.
  // Contacts are planar (contact_model.hpp), so this only removes rounding.
  void flatten() const;

  [[nodiscard]] dBodyID body() const { return body_; }

 private:
  dBodyID body_ = nullptr;
  double mass_kg_ = 0.0;
  double yaw_inertia_kg_m2_ = 0.0;
  double max_force_n_ = 0.0;
  double max_torque_nm_ = 0.0;
  double target_forward_mps_ = 0.0;
  double target_turn_rad_s_ = 0.0;
  void add_motors(dWorldID world, dJointGroupID group);

  DriveModel model_ = DriveModel::motor_joint_in_contact;
  dJointID linear_ = nullptr;  // persistent for motor_joint, per sub-step otherwise
  dJointID angular_ = nullptr;
};

// Yaw of a body, from its quaternion, in [-pi, pi].
double yaw_of(dBodyID body);
// Sets a body's orientation to a rotation of `yaw_rad` about z.
void set_yaw(dBodyID body, double yaw_rad);
// Returns a body exactly to the plane: z, vertical velocity, roll and pitch (and their rates) to
// zero. Contacts are planar (contact_model.hpp), so this only removes rounding.
void flatten_body(dBodyID body);

}  // namespace swarmnet::ode
