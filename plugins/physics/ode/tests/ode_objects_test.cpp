// Movable objects: a robot pushes a free box or cylinder, not one held by a wall or too heavy for
// its wheels' friction; proximity rays see objects; their poses are reported.
#include <gtest/gtest.h>

#include <cmath>

#include "ode_test_world.hpp"

namespace swarmnet::ode::testing {
namespace {

ArenaObject box_at(double x, double y, double size_m, double mass_kg) {
  ArenaObject box;
  box.shape = ArenaObject::Shape::box;
  box.position = Vec2(x, y);
  box.size_x_m = size_m;
  box.size_y_m = size_m;
  box.mass_kg = mass_kg;
  return box;
}

// Drives robot 0 straight at 0.3 m/s for `seconds`.
void drive_for(OdePhysics& physics, std::vector<RobotBody>& bodies, double seconds) {
  bodies[0].left_mps = bodies[0].right_mps = 0.3;
  for (int i = 0; i < static_cast<int>(std::lround(seconds / 0.1)); ++i) physics.step(0.1, bodies);
}

// A 0.3 m box of 0.5 kg resists with 0.5 * 0.5 kg * 9.81 = 2.45 N; the robot's wheels push with
// up to 17.7 N: it drives on at 0.3 m/s, pushing the box ahead of it.
TEST(OdeObjects, RobotPushesAFreeBox) {
  Arena arena = open_arena(10.0, 5.0);
  arena.objects.push_back(box_at(3.0, 2.5, 0.3, 0.5));
  std::vector<RobotBody> bodies = {robot_at(2.0, 2.5, 0.0)};
  auto physics = make_physics(arena, bodies);
  ASSERT_EQ(physics->object_poses().size(), 1U);
  EXPECT_EQ(physics->object_poses()[0].position, Vec2(3.0, 2.5));
  drive_for(*physics, bodies, 10.0);
  const ObjectPose box = physics->object_poses()[0];
  // Contact after 0.765 m, then 10 s * 0.3 m/s in all (less the 5 mm start-up lag): the box
  // ends about 2.23 m further on, still in contact with the robot's front.
  EXPECT_NEAR(box.position.x(), 3.0 + 3.0 - 0.765, 0.02);
  EXPECT_NEAR(box.position.x() - bodies[0].position.x(), 0.15 + 0.085, 0.005);
  EXPECT_NEAR(box.position.y(), 2.5, 0.005);
  EXPECT_NEAR(box.heading_rad, 0.0, 0.01);
}

// The same push towards the east wall with the box already touching it: it does not move.
TEST(OdeObjects, BoxAgainstAWallDoesNotMove) {
  Arena arena = open_arena(4.0, 5.0);
  arena.objects.push_back(box_at(4.0 - 0.15, 2.5, 0.3, 0.5));
  std::vector<RobotBody> bodies = {robot_at(3.0, 2.5, 0.0)};
  auto physics = make_physics(arena, bodies);
  drive_for(*physics, bodies, 5.0);
  const ObjectPose box = physics->object_poses()[0];
  EXPECT_NEAR(box.position.x(), 4.0 - 0.15, 0.005);  // pressed into the wall by < 5 mm
  EXPECT_NEAR(box.position.y(), 2.5, 1e-4);
  EXPECT_NEAR(bodies[0].position.x(), 4.0 - 0.3 - 0.085, 0.01);  // the robot stopped at the box
}

// A 10 kg box resists with 49 N, more than the 17.7 N the wheels can push with: it stays.
TEST(OdeObjects, BoxHeavierThanTheWheelsCanPushStays) {
  Arena arena = open_arena(10.0, 5.0);
  arena.objects.push_back(box_at(3.0, 2.5, 0.3, 10.0));
  std::vector<RobotBody> bodies = {robot_at(2.0, 2.5, 0.0)};
  auto physics = make_physics(arena, bodies);
  drive_for(*physics, bodies, 10.0);
  // Only the impact moves it: 1.8 kg at 0.3 m/s against a 49 N friction bound, about 1 mm.
  EXPECT_NEAR(physics->object_poses()[0].position.x(), 3.0, 0.003);
  EXPECT_NEAR(bodies[0].position.x(), 3.0 - 0.15 - 0.085, 0.01);
}

// A pushed cylinder released slides to a stop within v^2 / (2 mu g) (the floor friction's
// deceleration), and the proximity ring sees it.
TEST(OdeObjects, PushedCylinderSlidesToAStopAndIsSeen) {
  Arena arena = open_arena(10.0, 5.0);
  ArenaObject cylinder;
  cylinder.shape = ArenaObject::Shape::cylinder;
  cylinder.position = Vec2(3.0, 2.5);
  cylinder.radius_m = 0.1;
  cylinder.mass_kg = 0.3;
  arena.objects.push_back(cylinder);
  std::vector<RobotBody> bodies = {robot_at(2.0, 2.5, 0.0)};
  auto physics = make_physics(arena, bodies, {{"object_floor_friction", 0.2}});
  std::vector<double> rays(4);
  physics->sense_proximity(bodies, 0, 1.0, rays);
  EXPECT_NEAR(rays[0], 1.0 - 0.1 - 0.085, 1e-9);
  drive_for(*physics, bodies, 5.0);
  bodies[0].left_mps = bodies[0].right_mps = -0.3;  // back off: the cylinder coasts
  const double released_x = physics->object_poses()[0].position.x();
  for (int i = 0; i < 20; ++i) physics->step(0.1, bodies);
  const double slid_m = physics->object_poses()[0].position.x() - released_x;
  const double stopping_m = 0.3 * 0.3 / (2.0 * 0.2 * 9.81);  // 23 mm
  EXPECT_GT(slid_m, 0.5 * stopping_m);
  EXPECT_LT(slid_m, 1.2 * stopping_m);
  // At rest after 2 s: it stopped within 0.15 s.
  const double before = physics->object_poses()[0].position.x();
  physics->step(0.1, bodies);
  EXPECT_EQ(physics->object_poses()[0].position.x(), before);
}

TEST(OdeObjects, ProximityRaysSeeATurnedBox) {
  Arena arena = open_arena(10.0, 5.0);
  ArenaObject box = box_at(3.0, 2.5, 0.4, 1.0);
  box.size_y_m = 0.2;
  box.heading_rad = 0.5 * 3.141592653589793;  // its 0.4 m side along y, 0.2 m along x
  arena.objects.push_back(box);
  std::vector<RobotBody> bodies = {robot_at(2.0, 2.5, 0.0),
                                   robot_at(3.0, 1.0, 0.5 * 3.141592653589793)};
  auto physics = make_physics(arena, bodies);
  std::vector<double> rays(4);
  physics->sense_proximity(bodies, 0, 2.0, rays);
  EXPECT_NEAR(rays[0], 1.0 - 0.1 - 0.085, 1e-9);  // the face 0.1 m before the centre
  physics->sense_proximity(bodies, 1, 2.0, rays);
  EXPECT_NEAR(rays[0], 1.5 - 0.2 - 0.085, 1e-9);  // along +y: the face 0.2 m before the centre
}

}  // namespace
}  // namespace swarmnet::ode::testing
