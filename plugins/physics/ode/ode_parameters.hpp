// The physical constants of the ODE engine: one table, declared once with units and defaults,
// read into a struct the engine's parts share.
#pragma once

#include <vector>

#include "swarmnet/params.hpp"

namespace swarmnet::ode {

// How the wheels' friction drives the body (robot_drive.hpp).
enum class DriveModel { motor_joint_in_contact, motor_joint, servo_force };

struct OdeParameters {
  double robot_mass_kg = 1.8;
  double wheel_friction = 1.0;         // Coulomb coefficient, wheels on the floor
  double contact_friction = 0.3;       // Coulomb coefficient, body against body or wall
  double object_floor_friction = 0.5;  // Coulomb coefficient, movable objects on the floor
  double gravity_mps2 = 9.81;
  double contact_erp = 0.2;
  double contact_cfm_m_per_n = 1e-5;
  double contact_surface_layer_m = 0.001;
  double max_substep_s = 0.01;
  double max_travel_fraction = 0.5;
  int solver_iterations = 20;
  DriveModel drive = DriveModel::motor_joint_in_contact;

  // Every parameter at its declared default; used by the plugin's info() and its tests.
  static std::vector<ParamSpec> schema();
  static OdeParameters from(const ParamSet& params);
};

}  // namespace swarmnet::ode
