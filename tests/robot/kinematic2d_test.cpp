// kinematic2d: kinematics, collision guarantees and the proximity ring.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "robot/robot_placement.hpp"
#include "robot_test_support.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet {
namespace {

using test::make_body;
using test::make_physics;

double distance_to_rect(const Rect& rect, const Vec2& p) {
  const Vec2 nearest(std::clamp(p.x(), rect.x_min_m, rect.x_max_m),
                     std::clamp(p.y(), rect.y_min_m, rect.y_max_m));
  return (p - nearest).norm();
}

class Kinematic2dTest : public ::testing::Test {
 protected:
  PluginLoader loader_;
};

TEST_F(Kinematic2dTest, EqualWheelSpeedsDriveStraight) {
  auto physics = make_physics(loader_);
  const Arena arena{100.0, 100.0, {}};
  std::vector<RobotBody> bodies{make_body(20.0, 30.0, 0.3)};
  bodies[0].left_mps = bodies[0].right_mps = 0.7;
  physics->setup(arena, bodies);
  for (int i = 0; i < 30; ++i) physics->step(0.1, bodies);  // T = 3 s
  const Vec2 expected = Vec2(20.0, 30.0) + 0.7 * 3.0 * Vec2(std::cos(0.3), std::sin(0.3));
  EXPECT_LE((bodies[0].position - expected).norm(), 1e-9 * 0.7 * 3.0);
  EXPECT_EQ(bodies[0].heading_rad, 0.3);
}

TEST_F(Kinematic2dTest, UnequalWheelSpeedsFollowTheExactArc) {
  auto physics = make_physics(loader_);
  const Arena arena{100.0, 100.0, {}};
  const double left = 0.3;
  const double right = 0.5;
  const double axle = 0.14;
  const double heading0 = 0.4;
  const Vec2 start(50.0, 50.0);
  std::vector<RobotBody> bodies{make_body(start.x(), start.y(), heading0)};
  bodies[0].left_mps = left;
  bodies[0].right_mps = right;
  physics->setup(arena, bodies);

  const double v = 0.5 * (left + right);
  const double omega = (right - left) / axle;
  const double radius = v / omega;
  const Vec2 centre = start + radius * Vec2(-std::sin(heading0), std::cos(heading0));
  const double dt = 0.05;
  for (int i = 1; i <= 200; ++i) {
    physics->step(dt, bodies);
    const double t = dt * i;
    const double theta = heading0 + omega * t;
    const Vec2 expected(start.x() + radius * (std::sin(theta) - std::sin(heading0)),
                        start.y() - radius * (std::cos(theta) - std::cos(heading0)));
    ASSERT_NEAR(bodies[0].position.x(), expected.x(), 1e-9) << "step " << i;
    ASSERT_NEAR(bodies[0].position.y(), expected.y(), 1e-9) << "step " << i;
    ASSERT_NEAR((bodies[0].position - centre).norm(), radius, 1e-9);
    ASSERT_NEAR(std::remainder(bodies[0].heading_rad - theta, 2.0 * std::numbers::pi), 0.0, 1e-9);
  }
}

TEST_F(Kinematic2dTest, TurningInPlaceDoesNotMove) {
  auto physics = make_physics(loader_);
  const Arena arena{10.0, 10.0, {}};
  std::vector<RobotBody> bodies{make_body(5.0, 5.0, 0.0)};
  bodies[0].left_mps = -0.2;
  bodies[0].right_mps = 0.2;
  physics->setup(arena, bodies);
  physics->step(0.1, bodies);
  EXPECT_EQ(bodies[0].position, Vec2(5.0, 5.0));
  EXPECT_NEAR(bodies[0].heading_rad, 0.4 / 0.14 * 0.1, 1e-12);
}

TEST_F(Kinematic2dTest, RobotDrivenIntoAWallStopsAtIt) {
  auto physics = make_physics(loader_);
  const Arena arena{10.0, 10.0, {}};
  const double r = 0.085;
  std::vector<RobotBody> bodies{make_body(5.0, 2.0, 0.0, r)};
  bodies[0].left_mps = bodies[0].right_mps = 1.0;
  physics->setup(arena, bodies);
  for (int i = 0; i < 100; ++i) {
    physics->step(0.1, bodies);
    ASSERT_LE(bodies[0].position.x(), arena.width_m - r) << "step " << i;
  }
  EXPECT_NEAR(bodies[0].position.x(), arena.width_m - r, 1e-9);
  EXPECT_NEAR(bodies[0].position.y(), 2.0, 1e-12);
}

TEST_F(Kinematic2dTest, RobotAtAnAngleSlidesAlongTheWall) {
  auto physics = make_physics(loader_);
  const Arena arena{10.0, 10.0, {}};
  const double r = 0.085;
  const double heading = std::numbers::pi / 6.0;  // 30 degrees into the x = 10 wall
  std::vector<RobotBody> bodies{make_body(9.5, 2.0, heading, r)};
  bodies[0].left_mps = bodies[0].right_mps = 1.0;
  physics->setup(arena, bodies);
  for (int i = 0; i < 20; ++i) physics->step(0.1, bodies);
  EXPECT_NEAR(bodies[0].position.x(), arena.width_m - r, 1e-9);
  // The wall takes the normal component only: y advances as if unobstructed.
  EXPECT_NEAR(bodies[0].position.y(), 2.0 + 2.0 * std::sin(heading), 1e-9);
}

TEST_F(Kinematic2dTest, RobotDrivenIntoAnObstacleStopsAtIt) {
  const Rect block{6.0, 4.0, 8.0, 6.0};
  const Arena arena{20.0, 20.0, {block}};
  const double r = 0.085;
  // Drives one robot for 10 s, checking after every step that it stays out of the block; returns
  // its final pose and the closest it came to the block.
  auto drive = [&](const RobotBody& body) {
    auto physics = make_physics(loader_);
    std::vector<RobotBody> bodies{body};
    bodies[0].left_mps = bodies[0].right_mps = 1.0;
    physics->setup(arena, bodies);
    double closest = 1e9;
    for (int i = 0; i < 100; ++i) {
      physics->step(0.1, bodies);
      const double distance = distance_to_rect(block, bodies[0].position);
      EXPECT_GE(distance, r) << "step " << i;
      closest = std::min(closest, distance);
    }
    return std::pair{bodies[0], closest};
  };
  // Head-on into the left face.
  const auto [left, left_closest] = drive(make_body(2.0, 5.0, 0.0, r));
  EXPECT_NEAR(left.position.x(), block.x_min_m - r, 1e-6);
  EXPECT_NEAR(left.position.y(), 5.0, 1e-12);
  // Straight down onto the top face.
  const auto [top, top_closest] = drive(make_body(7.0, 9.0, -std::numbers::pi / 2, r));
  EXPECT_NEAR(top.position.y(), block.y_max_m + r, 1e-6);
  EXPECT_NEAR(top.position.x(), 7.0, 1e-12);
  // Diagonally at the top-left corner: it reaches the corner, and never gets inside.
  const auto [corner, corner_closest] = drive(make_body(3.0, 9.0, -std::numbers::pi / 4, r));
  EXPECT_NEAR(corner_closest, r, 1e-6);
}

TEST_F(Kinematic2dTest, HeadOnRobotsStopTouching) {
  auto physics = make_physics(loader_);
  const Arena arena{20.0, 20.0, {}};
  const double r = 0.085;
  std::vector<RobotBody> bodies{make_body(5.0, 5.0, 0.0, r),
                                make_body(7.0, 5.0, std::numbers::pi, r)};
  for (auto& body : bodies) body.left_mps = body.right_mps = 0.5;
  physics->setup(arena, bodies);
  for (int i = 0; i < 40; ++i) physics->step(0.1, bodies);
  const double gap = (bodies[1].position - bodies[0].position).norm();
  EXPECT_GE(gap, 2 * r);
  EXPECT_NEAR(gap, 2 * r, 1e-6);
  // Symmetric push: they meet in the middle.
  EXPECT_NEAR(0.5 * (bodies[0].position.x() + bodies[1].position.x()), 6.0, 1e-9);
}

// 500 robots at ~30% area fraction with an obstacle, random wheel speeds for 1000 steps: after
// every step no pair overlaps (all pairs checked), all are inside and clear of the obstacle, and
// they did move.
TEST_F(Kinematic2dTest, DenseSwarmNeverOverlaps) {
  auto physics = make_physics(loader_);
  const double r = 0.085;
  const std::uint32_t count = 500;
  const double side = std::sqrt(count * std::numbers::pi * r * r / 0.3 + 1.0);
  const Rect block{side / 2 - 0.5, side / 2 - 0.5, side / 2 + 0.5, side / 2 + 0.5};
  const Arena arena{side, side, {block}};
  RobotBody prototype = make_body(0, 0, 0, r);
  prototype.max_speed_mps = 1.0;
  std::vector<RobotBody> bodies = place_robots(arena, Rect{0, 0, side, side}, count, prototype, 42);
  const std::vector<RobotBody> start = bodies;
  physics->setup(arena, bodies);

  RandomStream random(7);
  double travelled = 0.0;
  for (int step = 0; step < 1000; ++step) {
    if (step % 20 == 0) {
      for (auto& body : bodies) {
        body.left_mps = random.uniform(-1.0, 1.0);
        body.right_mps = random.uniform(-1.0, 1.0);
      }
    }
    const std::vector<RobotBody> before = bodies;
    physics->step(0.1, bodies);
    for (std::size_t i = 0; i < count; ++i) {
      travelled += (bodies[i].position - before[i].position).norm();
      const Vec2& p = bodies[i].position;
      ASSERT_TRUE(p.x() >= r && p.x() <= side - r && p.y() >= r && p.y() <= side - r)
          << "robot " << i << " outside at step " << step;
      ASSERT_GE(distance_to_rect(block, p), r) << "robot " << i << " in obstacle at step " << step;
      for (std::size_t j = i + 1; j < count; ++j) {
        ASSERT_GE((bodies[j].position - p).squaredNorm(), (2 * r) * (2 * r))
            << "robots " << i << " and " << j << " overlap at step " << step;
      }
    }
  }
  // Mean path length per robot: collisions slow them, but most motion must survive.
  EXPECT_GT(travelled / count, 10.0);
  double displaced = 0.0;
  for (std::size_t i = 0; i < count; ++i)
    displaced += (bodies[i].position - start[i].position).norm();
  EXPECT_GT(displaced / count, 0.5);
}

TEST_F(Kinematic2dTest, SetupRefusesAnInvalidStart) {
  const Arena arena{10.0, 10.0, {Rect{4, 4, 6, 6}}};
  {
    auto physics = make_physics(loader_);
    std::vector<RobotBody> bodies{make_body(2.0, 2.0, 0), make_body(2.1, 2.0, 0)};
    EXPECT_THROW(physics->setup(arena, bodies), std::invalid_argument);
  }
  {
    auto physics = make_physics(loader_);
    std::vector<RobotBody> bodies{make_body(0.05, 2.0, 0)};
    EXPECT_THROW(physics->setup(arena, bodies), std::invalid_argument);
  }
  {
    auto physics = make_physics(loader_);
    std::vector<RobotBody> bodies{make_body(4.0, 3.95, 0)};
    EXPECT_THROW(physics->setup(arena, bodies), std::invalid_argument);
  }
  {
    auto physics = make_physics(loader_);
    // Exactly touching (0.25 = 0.125 + 0.125, all exact in binary) is allowed.
    std::vector<RobotBody> touching{make_body(2.0, 2.0, 0, 0.125), make_body(2.25, 2.0, 0, 0.125)};
    EXPECT_NO_THROW(physics->setup(arena, touching));
  }
}

TEST_F(Kinematic2dTest, ZeroIterationsStillKeepTheGuarantee) {
  auto physics = make_physics(loader_, {{"collision_iterations", std::int64_t{0}}});
  const Arena arena{10.0, 10.0, {}};
  const double r = 0.085;
  std::vector<RobotBody> bodies{make_body(5.0, 5.0, 0.0, r),
                                make_body(5.3, 5.0, std::numbers::pi, r),
                                make_body(9.85, 2.0, 0.0, r)};
  for (auto& body : bodies) body.left_mps = body.right_mps = 1.0;
  physics->setup(arena, bodies);
  physics->step(0.1, bodies);  // 0.3 apart, closing at 2 m/s: would overlap by 0.03
  EXPECT_EQ(bodies[0].position, Vec2(5.0, 5.0));
  EXPECT_EQ(bodies[1].position, Vec2(5.3, 5.0));
  EXPECT_EQ(bodies[2].position, Vec2(9.85, 2.0));  // would cross the wall: stays
}

TEST_F(Kinematic2dTest, ProximityReadsWallDistanceMinusRadius) {
  auto physics = make_physics(loader_);
  const Arena arena{10.0, 10.0, {}};
  const double r = 0.085;
  std::vector<RobotBody> bodies{make_body(3.0, 7.0, 0.0, r)};
  physics->setup(arena, bodies);
  std::vector<double> rays(4);
  physics->sense_proximity(bodies, 0, 20.0, rays);
  EXPECT_NEAR(rays[0], 7.0 - r, 1e-12);  // +x: wall at x = 10
  EXPECT_NEAR(rays[1], 3.0 - r, 1e-12);  // +y: wall at y = 10
  EXPECT_NEAR(rays[2], 3.0 - r, 1e-12);  // -x
  EXPECT_NEAR(rays[3], 7.0 - r, 1e-12);  // -y

  // Rays turn with the heading: ray 0 points along +y now.
  bodies[0].heading_rad = std::numbers::pi / 2;
  physics->setup(arena, bodies);
  physics->sense_proximity(bodies, 0, 20.0, rays);
  EXPECT_NEAR(rays[0], 3.0 - r, 1e-12);
  EXPECT_NEAR(rays[1], 3.0 - r, 1e-12);

  // A diagonal ray meets the wall at distance / cos(45 deg).
  std::vector<double> eight(8);
  bodies[0].heading_rad = 0.0;
  physics->setup(arena, bodies);
  physics->sense_proximity(bodies, 0, 20.0, eight);
  EXPECT_NEAR(eight[1], 3.0 * std::numbers::sqrt2 - r, 1e-12);  // 45 deg: the y = 10 wall first
}

TEST_F(Kinematic2dTest, ProximityReadsTheGapToAnotherRobot) {
  auto physics = make_physics(loader_);
  const Arena arena{10.0, 10.0, {}};
  const double r = 0.085;
  const double r2 = 0.1;
  std::vector<RobotBody> bodies{make_body(3.0, 5.0, 0.0, r), make_body(4.0, 5.0, 0.0, r2),
                                make_body(3.0 + 0.6 * std::cos(std::numbers::pi / 4),
                                          5.0 - 0.6 * std::sin(std::numbers::pi / 4), 0.0, r)};
  physics->setup(arena, bodies);
  std::vector<double> rays(8);
  physics->sense_proximity(bodies, 0, 2.0, rays);
  EXPECT_NEAR(rays[0], 1.0 - r - r2, 1e-12);  // robot ahead
  EXPECT_NEAR(rays[7], 0.6 - 2 * r, 1e-12);   // robot at -45 deg
  EXPECT_EQ(rays[4], 2.0);                    // behind: the wall at 3 m is out of range
  // And the robot ahead sees robot 0 behind it.
  physics->sense_proximity(bodies, 1, 2.0, rays);
  EXPECT_NEAR(rays[4], 1.0 - r - r2, 1e-12);
}

TEST_F(Kinematic2dTest, ProximityReadsAnObstacleFace) {
  auto physics = make_physics(loader_);
  const Arena arena{10.0, 10.0, {Rect{5.0, 4.0, 6.0, 8.0}}};
  const double r = 0.085;
  std::vector<RobotBody> bodies{make_body(3.0, 5.0, 0.0, r)};
  physics->setup(arena, bodies);
  std::vector<double> rays(4);
  physics->sense_proximity(bodies, 0, 5.0, rays);
  EXPECT_NEAR(rays[0], 2.0 - r, 1e-12);
  EXPECT_NEAR(rays[1], 5.0 - r, 1e-12);  // +y: the wall, passing beside the obstacle
  EXPECT_NEAR(rays[2], 3.0 - r, 1e-12);  // -x: the wall
}

// Brute force: every ray against every wall, obstacle and robot, with its own trigonometry.
std::vector<double> reference_rays(const Arena& arena, const std::vector<RobotBody>& bodies,
                                   std::size_t robot, double range_m, std::size_t count) {
  const RobotBody& self = bodies[robot];
  const Vec2 o = self.position;
  std::vector<double> result(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double angle = self.heading_rad + 2.0 * std::numbers::pi * k / count;
    const Vec2 u(std::cos(angle), std::sin(angle));
    double t = 1e300;
    if (u.x() > 0) t = std::min(t, (arena.width_m - o.x()) / u.x());
    if (u.x() < 0) t = std::min(t, -o.x() / u.x());
    if (u.y() > 0) t = std::min(t, (arena.height_m - o.y()) / u.y());
    if (u.y() < 0) t = std::min(t, -o.y() / u.y());
    for (const Rect& rect : arena.obstacles) {
      double enter = 0.0;
      double leave = 1e300;
      bool hit = true;
      for (int axis = 0; axis < 2; ++axis) {
        const double lo = axis == 0 ? rect.x_min_m : rect.y_min_m;
        const double hi = axis == 0 ? rect.x_max_m : rect.y_max_m;
        if (u[axis] == 0.0) {
          hit = hit && o[axis] >= lo && o[axis] <= hi;
          continue;
        }
        const double a = (lo - o[axis]) / u[axis];
        const double b = (hi - o[axis]) / u[axis];
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
      }
      if (hit && enter <= leave) t = std::min(t, enter);
    }
    for (std::size_t j = 0; j < bodies.size(); ++j) {
      if (j == robot) continue;
      const Vec2 d = bodies[j].position - o;
      const double b = u.dot(d);
      const double disc = b * b - (d.squaredNorm() - bodies[j].radius_m * bodies[j].radius_m);
      if (b > 0 && disc >= 0) t = std::min(t, b - std::sqrt(disc));
    }
    result[k] = std::clamp(t - self.radius_m, 0.0, range_m);
  }
  return result;
}

// The engine's grid lookup and angular pruning lose nothing: a dense random scene with robots of
// several sizes and obstacles reads the same as the brute-force reference.
TEST_F(Kinematic2dTest, ProximityMatchesBruteForce) {
  auto physics = make_physics(loader_);
  const Arena arena{8.0, 8.0, {Rect{2.0, 2.0, 3.0, 5.0}, Rect{5.0, 6.0, 7.5, 6.5}}};
  RandomStream random(3);
  std::vector<RobotBody> bodies;
  while (bodies.size() < 300) {
    const double r = random.uniform(0.05, 0.2);
    RobotBody body = make_body(random.uniform(r, 8.0 - r), random.uniform(r, 8.0 - r),
                               random.uniform(-std::numbers::pi, std::numbers::pi), r);
    bool free = distance_to_rect(arena.obstacles[0], body.position) >= r &&
                distance_to_rect(arena.obstacles[1], body.position) >= r;
    for (const auto& other : bodies) {
      free = free && (other.position - body.position).norm() >= r + other.radius_m;
    }
    if (free) bodies.push_back(body);
  }
  physics->setup(arena, bodies);
  for (const std::size_t count : {std::size_t{7}, std::size_t{24}, std::size_t{64}}) {
    std::vector<double> rays(count);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      physics->sense_proximity(bodies, i, 1.5, rays);
      const auto expected = reference_rays(arena, bodies, i, 1.5, count);
      for (std::size_t k = 0; k < count; ++k) {
        ASSERT_NEAR(rays[k], expected[k], 1e-9) << "robot " << i << " ray " << k << " of " << count;
      }
    }
  }
}

TEST_F(Kinematic2dTest, NothingInRangeReadsExactlyTheRange) {
  auto physics = make_physics(loader_);
  const Arena arena{10.0, 10.0, {}};
  std::vector<RobotBody> bodies{make_body(5.0, 5.0, 0.123), make_body(8.0, 5.0, 0.0)};
  physics->setup(arena, bodies);
  std::vector<double> rays(24);
  physics->sense_proximity(bodies, 0, 0.3, rays);
  for (double ray : rays) EXPECT_EQ(ray, 0.3);
}

}  // namespace
}  // namespace swarmnet
