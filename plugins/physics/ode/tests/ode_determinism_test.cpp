// Reruns are identical to the bit, also when two engines run interleaved in one process (ODE's
// solver generator is global to the library).
#include <gtest/gtest.h>

#include <cstring>

#include "ode_test_world.hpp"

namespace swarmnet::ode::testing {
namespace {

void drive(std::vector<RobotBody>& bodies, int step) {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const double phase = static_cast<double>((static_cast<int>(i) * 7 + step) % 23) / 23.0;
    bodies[i].left_mps = 0.8 * phase;
    bodies[i].right_mps = 0.8 * (1.0 - phase);
  }
}

bool same_bits(const std::vector<RobotBody>& a, const std::vector<RobotBody>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double xa[3] = {a[i].position.x(), a[i].position.y(), a[i].heading_rad};
    const double xb[3] = {b[i].position.x(), b[i].position.y(), b[i].heading_rad};
    if (std::memcmp(xa, xb, sizeof xa) != 0) return false;
  }
  return true;
}

TEST(OdeDeterminism, RerunsGiveIdenticalBitsEvenInterleaved) {
  const Arena arena = open_arena(6.0, 6.0);
  const std::vector<RobotBody> start = random_robots(arena, 150, 3);
  std::vector<RobotBody> first = start;
  auto physics_first = make_physics(arena, first);
  for (int step = 0; step < 300; ++step) {
    drive(first, step);
    physics_first->step(0.1, first);
  }
  std::vector<RobotBody> second = start;
  std::vector<RobotBody> third = start;
  auto physics_second = make_physics(arena, second);
  auto physics_third = make_physics(arena, third);
  for (int step = 0; step < 300; ++step) {
    drive(second, step);
    physics_second->step(0.1, second);
    drive(third, step);
    physics_third->step(0.1, third);
  }
  EXPECT_TRUE(same_bits(first, second));
  EXPECT_TRUE(same_bits(first, third));
  // The runs did something: robots moved and met.
  EXPECT_GT((first[0].position - start[0].position).norm(), 0.1);
}

}  // namespace
}  // namespace swarmnet::ode::testing
