// Initial placement: free of overlaps, inside the region, reproducible, clear when impossible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/robot_placement.hpp"

namespace swarmnet {
namespace {

RobotBody prototype(double radius_m = 0.085) {
  RobotBody body;
  body.radius_m = radius_m;
  return body;
}

TEST(PlacementTest, NoOverlapInsideTheRegionAndClearOfObstacles) {
  const Rect obstacle{5.0, 4.0, 7.0, 12.0};
  const Arena arena{20.0, 20.0, {obstacle}};
  const Rect region{2.0, 3.0, 12.0, 9.0};
  const double r = 0.085;
  const auto bodies = place_robots(arena, region, 400, prototype(r), 5);
  ASSERT_EQ(bodies.size(), 400U);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Vec2& p = bodies[i].position;
    EXPECT_TRUE(region.contains(p)) << i;
    EXPECT_TRUE(p.x() >= r && p.x() <= arena.width_m - r && p.y() >= r &&
                p.y() <= arena.height_m - r);
    const Vec2 nearest(std::clamp(p.x(), obstacle.x_min_m, obstacle.x_max_m),
                       std::clamp(p.y(), obstacle.y_min_m, obstacle.y_max_m));
    EXPECT_GE((p - nearest).norm(), r) << i;
    EXPECT_GE(bodies[i].heading_rad, -std::numbers::pi);
    EXPECT_LT(bodies[i].heading_rad, std::numbers::pi);
    EXPECT_EQ(bodies[i].radius_m, r);
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      ASSERT_GE((bodies[j].position - p).norm(), 2 * r) << i << " and " << j;
    }
  }
}

TEST(PlacementTest, RegionReachingOutsideTheArenaKeepsDiscsInside) {
  const Arena arena{5.0, 5.0, {}};
  const double r = 0.2;
  const auto bodies = place_robots(arena, Rect{-1.0, -1.0, 1.0, 6.0}, 12, prototype(r), 9);
  ASSERT_EQ(bodies.size(), 12U);
  for (const auto& body : bodies) {
    EXPECT_GE(body.position.x(), r);
    EXPECT_LE(body.position.x(), 1.0);
    EXPECT_GE(body.position.y(), r);
    EXPECT_LE(body.position.y(), 5.0 - r);
  }
}

TEST(PlacementTest, DeterministicForASeed) {
  const Arena arena{30.0, 30.0, {}};
  const auto a = place_robots(arena, Rect{0, 0, 30, 30}, 200, prototype(), 11);
  const auto b = place_robots(arena, Rect{0, 0, 30, 30}, 200, prototype(), 11);
  const auto c = place_robots(arena, Rect{0, 0, 30, 30}, 200, prototype(), 12);
  ASSERT_EQ(a.size(), b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].position, b[i].position);
    EXPECT_EQ(a[i].heading_rad, b[i].heading_rad);
    if (a[i].position != c[i].position) ++differ;
  }
  EXPECT_EQ(differ, a.size());
}

TEST(PlacementTest, TooSmallARegionIsAClearError) {
  const Arena arena{50.0, 50.0, {}};
  try {
    place_robots(arena, Rect{10, 10, 11, 11}, 100, prototype(), 3);
    FAIL() << "placing 100 robots in 1 m^2 succeeded";
  } catch (const std::runtime_error& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("of 100 robots"), std::string::npos) << text;
    EXPECT_NE(text.find("could place only"), std::string::npos) << text;
    EXPECT_NE(text.find("larger robots.placement"), std::string::npos) << text;
    // The count placed is stated and plausible for random packing of a 1 m square.
    const auto at = text.find("could place only ") + std::string("could place only ").size();
    const int placed = std::stoi(text.substr(at));
    EXPECT_GT(placed, 10);
    EXPECT_LT(placed, 100);
  }
}

TEST(PlacementTest, RegionOutsideTheArenaIsAClearError) {
  const Arena arena{10.0, 10.0, {}};
  EXPECT_THROW(place_robots(arena, Rect{20, 20, 30, 30}, 1, prototype(), 3), std::runtime_error);
  EXPECT_TRUE(place_robots(arena, Rect{20, 20, 30, 30}, 0, prototype(), 3).empty());
}

}  // namespace
}  // namespace swarmnet
