#include "robot_drive.hpp"

#include <algorithm>
#include <cmath>

namespace swarmnet::ode {

double yaw_of(dBodyID body) {
  const dReal* q = dBodyGetQuaternion(body);  // w, x, y, z
  return std::atan2(2.0 * (q[0] * q[3] + q[1] * q[2]), 1.0 - 2.0 * (q[2] * q[2] + q[3] * q[3]));
}

void set_yaw(dBodyID body, double yaw_rad) {
  const dQuaternion q = {std::cos(0.5 * yaw_rad), 0.0, 0.0, std::sin(0.5 * yaw_rad)};
  dBodySetQuaternion(body, q);
}

void RobotDrive::create(dWorldID world, dSpaceID space, const RobotBody& body, std::size_t index,
                        const OdeParameters& parameters) {
  body_ = dBodyCreate(world);
  dBodySetData(body_, reinterpret_cast<void*>(index + 1));
  dMass mass;
  // A cylinder along z (direction 3) as tall as it is wide; only its yaw inertia m r^2 / 2 acts.
  dMassSetCylinderTotal(&mass, parameters.robot_mass_kg, 3, body.radius_m, 2.0 * body.radius_m);
  dBodySetMass(body_, &mass);
  // Rotation integrated exactly over a sub-step (ODE's default, a normalised first-order
  // quaternion update, loses (w h)^3 / 12 rad per sub-step).
  dBodySetFiniteRotationMode(body_, 1);
  dBodySetPosition(body_, body.position.x(), body.position.y(), 0.0);
  set_yaw(body_, body.heading_rad);
  mass_kg_ = parameters.robot_mass_kg;
  yaw_inertia_kg_m2_ = mass.I[2 * 4 + 2];

  const dGeomID geom = dCreateSphere(space, body.radius_m);
  dGeomSetBody(geom, body_);

  max_force_n_ = parameters.wheel_friction * parameters.robot_mass_kg * parameters.gravity_mps2;
  max_torque_nm_ = max_force_n_ * 0.5 * body.axle_m;
  model_ = parameters.drive;
  if (model_ == DriveModel::motor_joint) add_motors(world, nullptr);
  command(body);
}

void RobotDrive::add_motors(dWorldID world, dJointGroupID group) {
  linear_ = dJointCreateLMotor(world, group);
  dJointAttach(linear_, body_, nullptr);
  dJointSetLMotorNumAxes(linear_, 2);
  // Axes attached to the body (rel = 1); ODE takes them in world coordinates at this call and
  // keeps them in the body's frame: along the heading and across it, as the body stands now.
  const double yaw_rad = yaw_of(body_);
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  dJointSetLMotorAxis(linear_, 0, 1, c, s, 0.0);
  dJointSetLMotorAxis(linear_, 1, 1, -s, c, 0.0);
  dJointSetLMotorParam(linear_, dParamFMax, max_force_n_);
  dJointSetLMotorParam(linear_, dParamFMax2, max_force_n_);
  dJointSetLMotorParam(linear_, dParamVel, target_forward_mps_);
  dJointSetLMotorParam(linear_, dParamVel2, 0.0);

  angular_ = dJointCreateAMotor(world, group);
  dJointAttach(angular_, body_, nullptr);
  dJointSetAMotorMode(angular_, dAMotorUser);
  dJointSetAMotorNumAxes(angular_, 1);
  dJointSetAMotorAxis(angular_, 0, 1, 0.0, 0.0, 1.0);
  dJointSetAMotorParam(angular_, dParamFMax, max_torque_nm_);
  dJointSetAMotorParam(angular_, dParamVel, target_turn_rad_s_);
}

void RobotDrive::command(const RobotBody& body) {
  target_forward_mps_ = 0.5 * (body.left_mps + body.right_mps);
  target_turn_rad_s_ = (body.right_mps - body.left_mps) / body.axle_m;
  if (model_ == DriveModel::motor_joint) {
    dJointSetLMotorParam(linear_, dParamVel, target_forward_mps_);
    dJointSetAMotorParam(angular_, dParamVel, target_turn_rad_s_);
  }
}

void RobotDrive::prepare(double h_s, bool in_contact, dWorldID world, dJointGroupID group) {
  if (model_ == DriveModel::motor_joint) return;
  if (model_ == DriveModel::motor_joint_in_contact && in_contact) {
    // Motors for this sub-step only, in the group emptied with the contacts after it.
    add_motors(world, group);
    return;
  }
  const dReal* q = dBodyGetQuaternion(body_);
  // Heading unit vector of a rotation about z: (cos, sin) of the yaw, from the quaternion.
  const double c = 1.0 - 2.0 * q[3] * q[3];
  const double s = 2.0 * q[0] * q[3];
  const dReal* v = dBodyGetLinearVel(body_);
  const double forward_mps = c * v[0] + s * v[1];
  const double sideways_mps = -s * v[0] + c * v[1];
  const double push_n =
      std::clamp(mass_kg_ * (target_forward_mps_ - forward_mps) / h_s, -max_force_n_, max_force_n_);
  const double hold_n =
      std::clamp(mass_kg_ * (0.0 - sideways_mps) / h_s, -max_force_n_, max_force_n_);
  dBodyAddForce(body_, c * push_n - s * hold_n, s * push_n + c * hold_n, 0.0);
  const double turn_rad_s = dBodyGetAngularVel(body_)[2];
  const double torque_nm = std::clamp(yaw_inertia_kg_m2_ * (target_turn_rad_s_ - turn_rad_s) / h_s,
                                      -max_torque_nm_, max_torque_nm_);
  dBodyAddTorque(body_, 0.0, 0.0, torque_nm);
}

void RobotDrive::read_pose(RobotBody& body) const {
  const dReal* p = dBodyGetPosition(body_);
  body.position = Vec2(p[0], p[1]);
  body.heading_rad = yaw_of(body_);
}

double RobotDrive::speed_mps() const {
  const dReal* v = dBodyGetLinearVel(body_);
  return std::sqrt(v[0] * v[0] + v[1] * v[1]);
}

void RobotDrive::flatten() const { flatten_body(body_); }

void flatten_body(dBodyID body) {
  const dReal* p = dBodyGetPosition(body);
  if (p[2] != 0.0) dBodySetPosition(body, p[0], p[1], 0.0);
  const dReal* v = dBodyGetLinearVel(body);
  if (v[2] != 0.0) dBodySetLinearVel(body, v[0], v[1], 0.0);
  const dReal* w = dBodyGetAngularVel(body);
  if (w[0] != 0.0 || w[1] != 0.0) dBodySetAngularVel(body, 0.0, 0.0, w[2]);
  const dReal* q = dBodyGetQuaternion(body);
  if (q[1] != 0.0 || q[2] != 0.0) set_yaw(body, yaw_of(body));
}

}  // namespace swarmnet::ode
