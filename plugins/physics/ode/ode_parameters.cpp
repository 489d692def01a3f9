#include "ode_parameters.hpp"

#include <string>

namespace swarmnet::ode {

std::vector<ParamSpec> OdeParameters::schema() {
  const OdeParameters d;
  return {
      real_param("robot_mass_kg", d.robot_mass_kg, "kg",
                 "mass of each robot, a uniform solid cylinder of the robot's radius (foot-bot: "
                 "about 1.8 kg)",
                 0.01, 1000.0),
      real_param("wheel_friction", d.wheel_friction, "",
                 "Coulomb coefficient of the wheels on the floor: the drive's force along and "
                 "across the heading is at most wheel_friction * mass * gravity, its yaw torque at "
                 "most that force * axle / 2; beyond it the robot slips",
                 0.0, 10.0),
      real_param("contact_friction", d.contact_friction, "",
                 "Coulomb coefficient between bodies in contact (robot-robot, robot-wall, "
                 "robot-obstacle), in the plane",
                 0.0, 10.0),
      real_param("object_floor_friction", d.object_floor_friction, "",
                 "Coulomb coefficient of movable objects (arena.objects) on the floor: a pushed "
                 "object resists with at most object_floor_friction * its mass * gravity",
                 0.0, 10.0),
      real_param("gravity_mps2", d.gravity_mps2, "m/s^2",
                 "gravity; only the normal force on the floor (mass * gravity) uses it", 0.0,
                 100.0),
      real_param("contact_erp", d.contact_erp, "",
                 "ODE error reduction parameter of contacts: the fraction of a penetration removed "
                 "per sub-step",
                 0.0, 1.0),
      real_param("contact_cfm_m_per_n", d.contact_cfm_m_per_n, "m/N",
                 "ODE constraint force mixing of contacts: softness; the contact acts as a spring "
                 "of stiffness ERP / (h * CFM) N/m for sub-step h",
                 0.0, 1.0),
      real_param("contact_surface_layer_m", d.contact_surface_layer_m, "m",
                 "penetration ODE tolerates without correcting it (avoids jitter in resting "
                 "contacts)",
                 0.0, 0.05),
      real_param("max_substep_s", d.max_substep_s, "s",
                 "longest ODE sub-step; a robot step of step_s is cut into at least "
                 "ceil(step_s / max_substep_s) equal sub-steps",
                 1e-5, 1.0),
      real_param("max_travel_fraction", d.max_travel_fraction, "",
                 "no body may move more than this fraction of the smallest robot radius in one "
                 "sub-step: the sub-step count grows with the fastest wheel or body speed, so that "
                 "nothing tunnels through a wall, an obstacle or a robot",
                 0.01, 1.0),
      integer_param("solver_iterations", d.solver_iterations, "",
                    "iterations of ODE's QuickStep solver per sub-step", 1, 1000),
      text_param("drive", "motor_joint_in_contact",
                 "how the wheels' friction drives the body: motor_joint (ODE velocity motors "
                 "bounded by the friction, solved with the contacts: exact static friction); "
                 "motor_joint_in_contact (the same, but a robot that touches nothing in a "
                 "sub-step gets the motors' solution as a force, skipping the solver: same "
                 "motion, several times faster); servo_force (always the force: a pushed robot "
                 "creeps and a pushing one droops)",
                 {"motor_joint_in_contact", "motor_joint", "servo_force"}),
  };
}

OdeParameters OdeParameters::from(const ParamSet& params) {
  OdeParameters p;
  p.robot_mass_kg = params.real("robot_mass_kg");
  p.wheel_friction = params.real("wheel_friction");
  p.contact_friction = params.real("contact_friction");
  p.object_floor_friction = params.real("object_floor_friction");
  p.gravity_mps2 = params.real("gravity_mps2");
  p.contact_erp = params.real("contact_erp");
  p.contact_cfm_m_per_n = params.real("contact_cfm_m_per_n");
  p.contact_surface_layer_m = params.real("contact_surface_layer_m");
  p.max_substep_s = params.real("max_substep_s");
  p.max_travel_fraction = params.real("max_travel_fraction");
  p.solver_iterations = static_cast<int>(params.integer("solver_iterations"));
  const std::string& drive = params.text("drive");
  p.drive = drive == "motor_joint"   ? DriveModel::motor_joint
            : drive == "servo_force" ? DriveModel::servo_force
                                     : DriveModel::motor_joint_in_contact;
  return p;
}

}  // namespace swarmnet::ode
