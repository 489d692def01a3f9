// The drive: straight runs, turns in place, the friction-bounded acceleration, sub-stepping.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "ode_test_world.hpp"

namespace swarmnet::ode::testing {
namespace {

constexpr double kGravity = 9.81;  // the default gravity_mps2

// From rest, the drive's force is capped at wheel_friction * m * g, so the robot accelerates at
// a = mu * g until it reaches v: it then lags a robot that had v from the start by v^2 / (2 a).
// ODE integrates semi-implicitly (velocity first, then position with the new velocity), which
// shortens the lag by v * h / 2 for sub-step h (10 ms here: 10 sub-steps per 0.1 s step).
TEST(OdeDrive, StraightDriveCoversSpeedTimesDurationAfterTheTransient) {
  for (const double speed_mps : {0.3, 1.0, 2.0}) {
    const Arena arena = open_arena(100.0, 10.0);
    std::vector<RobotBody> bodies = {robot_at(1.0, 5.0, 0.0)};
    auto physics = make_physics(arena, bodies);
    bodies[0].left_mps = bodies[0].right_mps = speed_mps;
    const double duration_s = 10.0;
    for (int i = 0; i < 100; ++i) physics->step(0.1, bodies);
    EXPECT_EQ(physics->last_substeps(), 10);
    const double h_s = 0.01;
    const double lag_m = speed_mps * speed_mps / (2.0 * 1.0 * kGravity) - speed_mps * h_s / 2.0;
    const double expected_m = speed_mps * duration_s - lag_m;
    // Tolerance 0.5 mm over 3 to 20 m: the last sub-step of the transient accelerates less than
    // a * h, which the closed form does not see (at most a * h^2 / 2 = 0.5 mm).
    EXPECT_NEAR(bodies[0].position.x() - 1.0, expected_m, 5e-4) << "at " << speed_mps << " m/s";
    EXPECT_NEAR(bodies[0].position.y(), 5.0, 1e-9);
    EXPECT_NEAR(bodies[0].heading_rad, 0.0, 1e-9);
    EXPECT_NEAR(physics->velocity(0).x(), speed_mps, 1e-6);
  }
}

// Both drive models push along the robot's heading, whatever it is at creation or later.
TEST(OdeDrive, DrivesAlongItsHeadingWithEitherDrive) {
  for (const char* drive : {"motor_joint_in_contact", "motor_joint", "servo_force"}) {
    for (const double heading_rad : {0.0, 2.0, -2.5}) {
      SCOPED_TRACE(std::string(drive) + " at " + std::to_string(heading_rad) + " rad");
      const Arena arena = open_arena(10.0, 10.0);
      std::vector<RobotBody> bodies = {robot_at(5.0, 5.0, heading_rad)};
      auto physics = make_physics(arena, bodies, {{"drive", std::string(drive)}});
      // A quarter turn in place, then straight on: 0.5 m/s for 2 s.
      bodies[0].left_mps = -0.11;
      bodies[0].right_mps = 0.11;
      for (int i = 0; i < 10; ++i) physics->step(0.1, bodies);
      const double turned_rad = bodies[0].heading_rad;
      const Vec2 start = bodies[0].position;
      bodies[0].left_mps = bodies[0].right_mps = 0.5;
      for (int i = 0; i < 20; ++i) physics->step(0.1, bodies);
      const Vec2 moved = bodies[0].position - start;
      EXPECT_NEAR(moved.norm(), 1.0 - 0.25 / (2.0 * kGravity) + 0.5 * 0.01 / 2.0, 5e-4);
      EXPECT_NEAR(std::atan2(moved.y(), moved.x()), turned_rad, 1e-6);
      EXPECT_NEAR(bodies[0].heading_rad, turned_rad, 1e-6);
    }
  }
}

TEST(OdeDrive, AccelerationIsBoundedByWheelFriction) {
  for (const double friction : {0.25, 0.5}) {
    for (const char* drive : {"motor_joint_in_contact", "motor_joint", "servo_force"}) {
      SCOPED_TRACE(drive);
      const Arena arena = open_arena(20.0, 10.0);
      std::vector<RobotBody> bodies = {robot_at(1.0, 5.0, 0.0)};
      auto physics = make_physics(arena, bodies,
                                  {{"wheel_friction", friction}, {"drive", std::string(drive)}});
      bodies[0].left_mps = bodies[0].right_mps = 2.0;
      physics->step(0.1, bodies);
      // After 0.1 s at mu * g: 0.245 or 0.49 m/s, well below the 2 m/s commanded.
      EXPECT_NEAR(physics->velocity(0).x(), friction * kGravity * 0.1, 1e-9);
    }
  }
}

// Heading is unwrapped step by step: the robot turns more than a full turn.
TEST(OdeDrive, TurnsInPlaceAtTheRateTheAxleGives) {
  const Arena arena = open_arena(10.0, 10.0);
  std::vector<RobotBody> bodies = {robot_at(5.0, 5.0, 0.5)};
  auto physics = make_physics(arena, bodies);
  bodies[0].left_mps = -0.1;
  bodies[0].right_mps = 0.1;
  const double rate_rad_s = 0.2 / bodies[0].axle_m;  // (right - left) / axle
  double turned_rad = 0.0;
  double previous = bodies[0].heading_rad;
  for (int i = 0; i < 50; ++i) {
    physics->step(0.1, bodies);
    turned_rad += std::remainder(bodies[0].heading_rad - previous, 2.0 * std::numbers::pi);
    previous = bodies[0].heading_rad;
  }
  // The yaw torque limit mu m g axle / 2 against the inertia m r^2 / 2 allows an angular
  // acceleration of mu g axle / r^2 = 190 rad/s^2, 1.9 rad/s in one 10 ms sub-step: more than
  // the 1.43 rad/s asked, so the robot turns at the full rate from the first sub-step on.
  const double alpha = kGravity * bodies[0].axle_m / (bodies[0].radius_m * bodies[0].radius_m);
  ASSERT_GT(alpha * 0.01, rate_rad_s);
  // Tolerance 1e-6 rad over 7.14 rad: QuickStep solves the yaw motor iteratively (1e-8 relative).
  EXPECT_NEAR(turned_rad, rate_rad_s * 5.0, 1e-6);
  EXPECT_NEAR(bodies[0].position.x(), 5.0, 1e-9);
  EXPECT_NEAR(bodies[0].position.y(), 5.0, 1e-9);
}

TEST(OdeDrive, SubstepsKeepEveryMoveBelowTheTravelLimit) {
  const Arena arena = open_arena(100.0, 10.0);
  std::vector<RobotBody> bodies = {robot_at(1.0, 5.0), robot_at(3.0, 5.0)};
  auto physics = make_physics(arena, bodies);
  // At rest: ceil(0.1 s / max_substep_s 0.01 s).
  EXPECT_EQ(physics->substeps_for(0.1, bodies), 10);
  // At 5 m/s: 0.5 m per step, at most half of 0.085 m per sub-step: ceil(0.5 / 0.0425) = 12.
  bodies[1].left_mps = 5.0;
  bodies[1].right_mps = 5.0;
  EXPECT_EQ(physics->substeps_for(0.1, bodies), 12);
  physics->step(0.1, bodies);
  EXPECT_EQ(physics->last_substeps(), 12);
  // A longer step needs proportionally more.
  EXPECT_EQ(physics->substeps_for(0.5, bodies), 59);
  // A body still moving counts even when its wheels stop.
  for (int i = 0; i < 10; ++i) physics->step(0.1, bodies);
  bodies[1].left_mps = bodies[1].right_mps = 0.0;
  EXPECT_EQ(physics->substeps_for(0.1, bodies), 12);
}

TEST(OdeDrive, ListsEveryParameterWithItsUnit) {
  const PluginInfo info = OdePhysics::info();
  EXPECT_EQ(info.name, "ode");
  std::vector<std::pair<std::string, std::string>> listed;
  for (const ParamSpec& spec : info.params) {
    listed.emplace_back(spec.name, spec.unit);
    EXPECT_FALSE(spec.help.empty()) << spec.name;
  }
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"robot_mass_kg", "kg"},        {"wheel_friction", ""},           {"contact_friction", ""},
      {"object_floor_friction", ""},  {"gravity_mps2", "m/s^2"},        {"contact_erp", ""},
      {"contact_cfm_m_per_n", "m/N"}, {"contact_surface_layer_m", "m"}, {"max_substep_s", "s"},
      {"max_travel_fraction", ""},    {"solver_iterations", ""},        {"drive", ""},
  };
  EXPECT_EQ(listed, expected);
}

}  // namespace
}  // namespace swarmnet::ode::testing
