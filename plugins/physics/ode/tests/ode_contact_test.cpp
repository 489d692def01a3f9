// Contacts: walls and obstacles stop robots, nothing tunnels at 5 m/s, a dense swarm stays
// apart, and the proximity ring sees the same geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ode_test_world.hpp"

namespace swarmnet::ode::testing {
namespace {

// Soft contacts yield a little: the stated bound on any interpenetration, m.
constexpr double kMaxPenetrationM = 0.005;

TEST(OdeContact, WallStopsARobot) {
  const Arena arena = open_arena(5.0, 5.0);
  std::vector<RobotBody> bodies = {robot_at(2.5, 2.5, 0.0)};
  auto physics = make_physics(arena, bodies);
  bodies[0].left_mps = bodies[0].right_mps = 1.0;
  for (int i = 0; i < 50; ++i) physics->step(0.1, bodies);  // would be 5 m: 2.4 m to the wall
  const double contact_x = arena.width_m - bodies[0].radius_m;
  EXPECT_LE(bodies[0].position.x(), contact_x + kMaxPenetrationM);
  EXPECT_GE(bodies[0].position.x(), contact_x - kMaxPenetrationM);
  EXPECT_NEAR(physics->velocity(0).x(), 0.0, 1e-3);
  EXPECT_NEAR(bodies[0].position.y(), 2.5, 1e-6);
}

// The step sizes of the study (0.1 s) and a coarse one (0.5 s), robots at 5 m/s: 0.5 and 2.5 m
// per step against a 0.17 m robot. Sub-steps keep each body's move under max_travel_fraction
// (0.5) of the radius, so a centre never gets past a surface: at every step's end a robot is on
// its side of the wall and of the robot it meets, overlapping by less than half a radius (one
// mover) or a radius (two, head-on); once stopped, it rests at contact within kMaxPenetrationM.
TEST(OdeContact, NoTunnellingAtFiveMetresPerSecond) {
  for (const double step_s : {0.1, 0.5}) {
    SCOPED_TRACE("step_s " + std::to_string(step_s));
    // A wall 0.01 m thick across the arena at x = 3, robot 0 driving at it; robots 1 and 2
    // driving head-on at each other; robot 3 driving at the east wall.
    Arena arena = open_arena(10.0, 6.0);
    arena.obstacles.push_back(Rect{3.0, 0.0, 3.01, 3.0});
    std::vector<RobotBody> bodies = {robot_at(1.0, 1.5, 0.0), robot_at(4.0, 4.5, 0.0),
                                     robot_at(8.0, 4.5, std::numbers::pi), robot_at(6.0, 1.5, 0.0)};
    auto physics = make_physics(arena, bodies);
    for (RobotBody& body : bodies) body.left_mps = body.right_mps = 5.0;
    const double r = bodies[0].radius_m;
    for (int i = 0; i < static_cast<int>(std::lround(4.0 / step_s)); ++i) {
      physics->step(step_s, bodies);
      EXPECT_LE(bodies[0].position.x(), 3.0 - 0.5 * r);
      EXPECT_LT(bodies[1].position.x(), bodies[2].position.x());
      EXPECT_GE((bodies[2].position - bodies[1].position).norm(), r);
      EXPECT_LE(bodies[3].position.x(), arena.width_m - 0.5 * r);
    }
    EXPECT_NEAR(bodies[0].position.x(), 3.0 - r, kMaxPenetrationM);
    EXPECT_NEAR(bodies[3].position.x(), arena.width_m - r, kMaxPenetrationM);
  }
}

// 300 robots at random in 8 x 8 m (36% of the floor covered), each driving at 0.5 m/s and
// turning (wheels 0.2 and 0.8 m/s) a random way for a while when its front rays see something.
// Contacts are found only once bodies overlap, so two robots closing at u m/s may overlap by up
// to u * h in a sub-step h before the contact pushes them apart (ERP removes it over the next
// sub-steps). The stated bound is therefore 2 * 0.8 m/s * h + the surface layer (1 mm): 17 mm at
// the default 10 ms sub-step (a tenth of the radius), 4.2 mm at 2 ms.
void expect_dense_swarm_stays_apart(double substep_s, int steps) {
  SCOPED_TRACE("max_substep_s " + std::to_string(substep_s));
  const Arena arena = open_arena(8.0, 8.0);
  std::vector<RobotBody> bodies = random_robots(arena, 300, 11);
  auto physics = make_physics(arena, bodies, {{"max_substep_s", substep_s}});
  const double bound_m = 2.0 * 0.8 * substep_s + 0.001;
  RandomStream random(5);
  std::vector<double> rays(8);
  std::vector<int> turning(bodies.size(), 0);
  double deepest_m = 0.0;
  double outside_m = 0.0;
  std::size_t contacts = 0;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      physics->sense_proximity(bodies, i, 0.1, rays);
      if (turning[i] == 0 && std::min({rays[0], rays[1], rays[7]}) < 0.05) {
        turning[i] = random.bernoulli(0.5) ? 5 : -5;
      }
      const double turn = turning[i] > 0 ? 1.0 : (turning[i] < 0 ? -1.0 : 0.0);
      bodies[i].left_mps = 0.5 - 0.3 * turn;
      bodies[i].right_mps = 0.5 + 0.3 * turn;
      turning[i] -= turning[i] > 0 ? 1 : (turning[i] < 0 ? -1 : 0);
    }
    physics->step(0.1, bodies);
    contacts = std::max(contacts, physics->last_contact_count());
    deepest_m = std::max(deepest_m, deepest_penetration(bodies));
    for (const RobotBody& body : bodies) {
      const double r = body.radius_m;
      outside_m =
          std::max({outside_m, r - body.position.x(), r - body.position.y(),
                    body.position.x() + r - arena.width_m, body.position.y() + r - arena.height_m});
    }
  }
  EXPECT_GT(contacts, 10U);  // the swarm is dense enough to collide
  EXPECT_LE(deepest_m, bound_m);
  EXPECT_LE(outside_m, bound_m);
}

TEST(OdeContact, DenseSwarmStaysApartForAThousandSteps) {
  expect_dense_swarm_stays_apart(0.01, 1000);
}

TEST(OdeContact, DenseSwarmOverlapShrinksWithTheSubstep) {
  expect_dense_swarm_stays_apart(0.002, 300);
}

// Two equal robots driving into each other at 0.3 m/s push with the same traction: they stop at
// contact and stay there, neither gaining ground.
TEST(OdeContact, EqualRobotsPushingHeadOnStall) {
  const Arena arena = open_arena(10.0, 5.0);
  std::vector<RobotBody> bodies = {robot_at(4.0, 2.5, 0.0), robot_at(6.0, 2.5, std::numbers::pi)};
  auto physics = make_physics(arena, bodies);
  for (RobotBody& body : bodies) body.left_mps = body.right_mps = 0.3;
  for (int i = 0; i < 50; ++i) physics->step(0.1, bodies);
  const double left_x = bodies[0].position.x();
  for (int i = 0; i < 50; ++i) physics->step(0.1, bodies);
  EXPECT_NEAR(bodies[0].position.x(), left_x, 1e-6);
  EXPECT_NEAR(bodies[0].position.x() + bodies[1].position.x(), 10.0, 1e-6);  // the middle
  EXPECT_NEAR(bodies[1].position.x() - bodies[0].position.x(), 0.17, kMaxPenetrationM);
  EXPECT_NEAR(physics->velocity(0).norm(), 0.0, 1e-6);
}

TEST(OdeContact, ProximityRaysSeeWallsObstaclesAndRobots) {
  Arena arena = open_arena(10.0, 10.0);
  arena.obstacles.push_back(Rect{5.0, 8.0, 6.0, 9.0});
  // Robot 0 faces +x: a robot 0.3 m ahead (0.13 m gap), the obstacle 0.5 m to its left (+y),
  // the west wall 5 m behind it (out of range).
  std::vector<RobotBody> bodies = {robot_at(5.5, 7.415, 0.0), robot_at(5.8, 7.415, 0.0)};
  auto physics = make_physics(arena, bodies);
  std::vector<double> rays(4);
  physics->sense_proximity(bodies, 0, 1.0, rays);
  EXPECT_NEAR(rays[0], 0.3 - 2 * 0.085, 1e-9);      // ahead: robot 1
  EXPECT_NEAR(rays[1], 8.0 - 7.415 - 0.085, 1e-9);  // left: the obstacle
  EXPECT_DOUBLE_EQ(rays[2], 1.0);                   // behind: nothing within range
  EXPECT_DOUBLE_EQ(rays[3], 1.0);                   // right: the south wall is 7.4 m away
  physics->sense_proximity(bodies, 1, 5.0, rays);
  EXPECT_NEAR(rays[0], 10.0 - 5.8 - 0.085, 1e-9);  // the east wall
  EXPECT_NEAR(rays[2], 0.3 - 2 * 0.085, 1e-9);     // robot 0 behind
}

}  // namespace
}  // namespace swarmnet::ode::testing
