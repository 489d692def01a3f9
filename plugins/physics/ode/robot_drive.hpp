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
// Two implementations of the servo (parameter `drive`):
//   - "servo_force" (default): before every sub-step, the force (and torque) that would bring the
//     body to its target velocity within the sub-step, clipped to the friction limit, is applied
//     to the body. No constraint rows: a robot that touches nothing is integrated without the
//     solver, which makes this about twice as fast in a diffusing swarm.
//   - "motor_joint": an ODE linear motor (two body-frame axes) and angular motor with the same
//     targets and limits, solved together with the contacts by QuickStep. For a free robot both
//     give the same motion; in a contact they differ in that the joint's force is solved
//     simultaneously with the contact forces, the servo's from the velocity before the sub-step.
//
// The body is a uniform solid cylinder of the robot's radius (for its inertia) and collides as a
// sphere of that radius centred on z = 0: in the plane, the disc of the robot.
#pragma once

#include <ode/ode.h>

#include "ode_parameters.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet::ode {

class RobotDrive {
 public:
  // Creates the body, its geom in `space` and, for the motor_joint drive, its motors, at
  // `body`'s pose, at rest.
  void create(dWorldID world, dSpaceID space, const RobotBody& body,
              const OdeParameters& parameters);

  // Sets the servo's targets from the wheel speeds in `body` (left_mps, right_mps, axle_m).
  void command(const RobotBody& body);

  // servo_force: applies the bounded force and torque towards the targets for a sub-step of
  // h_s seconds (ODE clears accumulated forces after each step). No-op for motor_joint.
  void apply_servo(double h_s) const;

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
  bool servo_ = true;
  dJointID linear_ = nullptr;
  dJointID angular_ = nullptr;
};

// Yaw of a body, from its quaternion, in [-pi, pi].
double yaw_of(dBodyID body);
// Sets a body's orientation to a rotation of `yaw_rad` about z.
void set_yaw(dBodyID body, double yaw_rad);

}  // namespace swarmnet::ode
