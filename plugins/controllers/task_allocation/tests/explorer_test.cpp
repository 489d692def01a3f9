// explorer: cells inside the arena, marking, targets and the memory reset.
#include "explorer.hpp"

#include <gtest/gtest.h>

#include <set>

namespace swarmnet::task_allocation {
namespace {

bool inside(const Arena& arena, const Vec2& p) {
  return p.x() > 0.0 && p.x() < arena.width_m && p.y() > 0.0 && p.y() < arena.height_m;
}

TEST(TaskAllocationExplorerTest, CellsCoverTheArenaAndStayInside) {
  const Arena square{500.0, 500.0, {}};
  const Explorer grid(square, 50.0, 150.0);
  EXPECT_EQ(grid.cell_count(), 100U);
  EXPECT_EQ(grid.centre(0), Vec2(25.0, 25.0));
  EXPECT_EQ(grid.centre(99), Vec2(475.0, 475.0));

  const Arena odd{130.0, 70.0, {}};  // 3 x 2 cells of 43.3 x 35 m
  const Explorer small(odd, 50.0, 150.0);
  ASSERT_EQ(small.cell_count(), 6U);
  for (std::size_t i = 0; i < small.cell_count(); ++i) EXPECT_TRUE(inside(odd, small.centre(i)));
  EXPECT_NEAR(small.centre(5).x(), 130.0 - 130.0 / 6.0, 1e-9);
  EXPECT_NEAR(small.centre(5).y(), 52.5, 1e-9);
}

TEST(TaskAllocationExplorerTest, ACellIsExploredWithinHalfACellOfItsCentre) {
  Explorer grid(Arena{500.0, 500.0, {}}, 50.0, 150.0);
  grid.observe(Vec2(25.0, 50.0));  // 25 m from the centres of cells 0 and 10
  EXPECT_TRUE(grid.explored(0));
  EXPECT_TRUE(grid.explored(10));
  EXPECT_FALSE(grid.explored(1));  // (75, 25): 55.9 m
  EXPECT_EQ(grid.explored_count(), 2U);
  grid.observe(Vec2(100.0, 60.0));  // 29.2 m from (75, 75) and (125, 75)
  EXPECT_EQ(grid.explored_count(), 2U);
}

TEST(TaskAllocationExplorerTest, ObstacleCellsNeverCount) {
  Arena arena{100.0, 100.0, {Rect{0.0, 0.0, 60.0, 60.0}}};
  Explorer grid(arena, 50.0, 150.0);
  EXPECT_TRUE(grid.explored(0));  // its centre (25, 25) is inside the obstacle
  RandomStream random(1);
  for (int i = 0; i < 50; ++i) {
    const Vec2 t = grid.target(Vec2(90.0, 90.0), random);
    EXPECT_NE(t, grid.centre(0));
    grid.drop_target();
  }
}

TEST(TaskAllocationExplorerTest, TargetsAreUnexploredCellsAndNearOnesArePreferred) {
  const Arena arena{500.0, 500.0, {}};
  Explorer grid(arena, 50.0, 50.0);
  RandomStream random(3);
  const Vec2 at(30.0, 30.0);
  grid.observe(at);
  int near = 0;
  for (int i = 0; i < 1000; ++i) {
    const Vec2 t = grid.target(at, random);
    ASSERT_TRUE(grid.target_cell().has_value());
    EXPECT_FALSE(grid.explored(*grid.target_cell()));
    EXPECT_TRUE(inside(arena, t));
    if ((t - at).norm() < 80.0) ++near;
    grid.drop_target();
  }
  // The three next cells (50 m and 70.7 m away) dominate a scale of 50 m.
  EXPECT_GT(near, 500);
}

TEST(TaskAllocationExplorerTest, DrivingToTargetsExploresEverythingThenStartsOver) {
  const Arena arena{300.0, 200.0, {}};
  Explorer grid(arena, 50.0, 150.0);
  RandomStream random(5);
  Vec2 at(10.0, 10.0);
  std::set<std::size_t> visited;
  for (int leg = 0; leg < 24; ++leg) {  // 24 cells: every cell is reached at most once
    const Vec2 t = grid.target(at, random);
    EXPECT_TRUE(inside(arena, t));
    visited.insert(*grid.target_cell());
    at = t;  // teleport there
    grid.observe(at);
    if (grid.explored_count() == grid.cell_count()) break;
  }
  EXPECT_EQ(grid.explored_count(), grid.cell_count());
  // The next target clears the memory: only the cell under the robot stays explored.
  const Vec2 next = grid.target(at, random);
  EXPECT_EQ(grid.explored_count(), 1U);
  EXPECT_NE(next, at);
  EXPECT_FALSE(grid.explored(*grid.target_cell()));
}

TEST(TaskAllocationExplorerTest, KeepsItsTargetUntilExplored) {
  Explorer grid(Arena{500.0, 500.0, {}}, 50.0, 150.0);
  RandomStream random(9);
  const Vec2 first = grid.target(Vec2(250.0, 250.0), random);
  EXPECT_EQ(grid.target(Vec2(260.0, 250.0), random), first);
  grid.observe(first);
  EXPECT_NE(grid.target(first, random), first);
}

}  // namespace
}  // namespace swarmnet::task_allocation
