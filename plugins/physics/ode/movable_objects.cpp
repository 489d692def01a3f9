#include "movable_objects.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "robot_drive.hpp"

namespace swarmnet::ode {

void MovableObjects::create(dWorldID world, dSpaceID space, std::span<const ArenaObject> objects,
                            const OdeParameters& parameters) {
  bodies_.clear();
  poses_.clear();
  smallest_half_extent_m_ = 0.0;
  for (const ArenaObject& object : objects) {
    Body made;
    made.body = dBodyCreate(world);
    dMass mass;
    dGeomID geom = nullptr;
    double disc_radius_m = object.radius_m;
    double half_extent_m = object.radius_m;
    if (object.shape == ArenaObject::Shape::box) {
      dMassSetBoxTotal(&mass, object.mass_kg, object.size_x_m, object.size_y_m, kObjectHeightM);
      geom = dCreateBox(space, object.size_x_m, object.size_y_m, kObjectHeightM);
      disc_radius_m = std::sqrt(object.size_x_m * object.size_y_m / std::numbers::pi);
      half_extent_m = 0.5 * std::min(object.size_x_m, object.size_y_m);
    } else {
      dMassSetCylinderTotal(&mass, object.mass_kg, 3, object.radius_m, kObjectHeightM);
      geom = dCreateSphere(space, object.radius_m);
    }
    dBodySetMass(made.body, &mass);
    dBodySetFiniteRotationMode(made.body, 1);
    dBodySetPosition(made.body, object.position.x(), object.position.y(), 0.0);
    set_yaw(made.body, object.heading_rad);
    dGeomSetBody(geom, made.body);
    const double max_force_n =
        parameters.object_floor_friction * object.mass_kg * parameters.gravity_mps2;
    // Floor friction as velocity motors with target 0 and the Coulomb bound, solved together with
    // the contacts, so that static friction holds exactly (an explicit force computed from the
    // velocity before the sub-step would let a pushed object creep).
    const dJointID sliding = dJointCreateLMotor(world, nullptr);
    dJointAttach(sliding, made.body, nullptr);
    dJointSetLMotorNumAxes(sliding, 2);
    dJointSetLMotorAxis(sliding, 0, 0, 1.0, 0.0, 0.0);  // world x
    dJointSetLMotorAxis(sliding, 1, 0, 0.0, 1.0, 0.0);  // world y
    dJointSetLMotorParam(sliding, dParamVel, 0.0);
    dJointSetLMotorParam(sliding, dParamVel2, 0.0);
    dJointSetLMotorParam(sliding, dParamFMax, max_force_n);
    dJointSetLMotorParam(sliding, dParamFMax2, max_force_n);
    const dJointID spinning = dJointCreateAMotor(world, nullptr);
    dJointAttach(spinning, made.body, nullptr);
    dJointSetAMotorMode(spinning, dAMotorUser);
    dJointSetAMotorNumAxes(spinning, 1);
    dJointSetAMotorAxis(spinning, 0, 0, 0.0, 0.0, 1.0);
    dJointSetAMotorParam(spinning, dParamVel, 0.0);
    dJointSetAMotorParam(spinning, dParamFMax, max_force_n * 2.0 / 3.0 * disc_radius_m);
    bodies_.push_back(made);
    smallest_half_extent_m_ = smallest_half_extent_m_ == 0.0
                                  ? half_extent_m
                                  : std::min(smallest_half_extent_m_, half_extent_m);
  }
  poses_.resize(bodies_.size());
  read_poses();
}

void MovableObjects::read_poses() {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const dBodyID body = bodies_[i].body;
    flatten_body(body);
    const dReal* p = dBodyGetPosition(body);
    poses_[i].position = Vec2(p[0], p[1]);
    poses_[i].heading_rad = yaw_of(body);
  }
}

double MovableObjects::fastest_mps() const {
  double fastest = 0.0;
  for (const Body& b : bodies_) {
    const dReal* v = dBodyGetLinearVel(b.body);
    fastest = std::max(fastest, std::sqrt(v[0] * v[0] + v[1] * v[1]));
  }
  return fastest;
}

}  // namespace swarmnet::ode
