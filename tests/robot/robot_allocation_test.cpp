// The robot half's hot loop does not allocate once warmed up (DESIGN.md section 7). Global
// operator new is replaced in this executable (plugins loaded into it use it too) and counts
// allocations while a step runs.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "robot/robot_world.hpp"
#include "robot_test_support.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<std::size_t> allocations{0};

}  // namespace

void* operator new(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// Not inlined: GCC would otherwise see free() applied to what operator new returned and warn.
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace swarmnet {
namespace {

using test::make_choice;
using test::make_settings;

std::size_t allocations_during(const auto& action) {
  allocations = 0;
  counting = true;
  action();
  counting = false;
  return allocations.load();
}

// The replacement reaches code inside plugin libraries: physics setup() allocates its buffers
// there and nowhere else.
TEST(RobotAllocationTest, CountingSeesPluginAllocations) {
  PluginLoader loader;
  auto physics = test::make_physics(loader);
  const Arena arena{10.0, 10.0, {}};
  const std::vector<RobotBody> bodies{test::make_body(2.0, 2.0, 0.0),
                                      test::make_body(5.0, 5.0, 0.0)};
  EXPECT_GT(allocations_during([&] { physics->setup(arena, bodies); }), 0U);
}

TEST(RobotAllocationTest, DenseDiffusingSwarmStepsWithoutAllocating) {
  PluginLoader loader;
  RobotSettings settings = make_settings(loader, 400, 12.0, 12.0);
  settings.arena.obstacles.push_back(Rect{5.0, 5.0, 7.0, 6.0});
  settings.robots.controllers.push_back(
      make_choice(loader, "diffusion", PluginKind::controller, {{"turn_interval_s", 1.0}}));
  RobotWorld world(settings, loader);
  std::vector<AppMessage> sent;
  world.step({}, sent);
  EXPECT_EQ(allocations_during([&] {
              for (int i = 0; i < 200; ++i) world.step({}, sent);
            }),
            0U);
}

// The range-and-bearing device reuses its readings and scratch space: once they have grown, a
// swarm in which the same robots see each other senses without allocating (noise on; no loss,
// so that the count of readings stays the same).
TEST(RobotAllocationTest, RangeAndBearingSensesWithoutAllocating) {
  PluginLoader loader;
  RobotSettings settings = make_settings(loader, 400, 12.0, 12.0);
  settings.arena.obstacles.push_back(Rect{5.0, 5.0, 7.0, 6.0});
  settings.robots.range_and_bearing.enabled = true;
  settings.robots.range_and_bearing.range_noise_sd_m = 0.01;
  settings.robots.range_and_bearing.bearing_noise_sd_rad = 0.01;
  RobotWorld world(settings, loader);
  std::vector<AppMessage> sent;
  world.step({}, sent);
  std::size_t readings = 0;
  for (RobotId r = 0; r < 400; ++r) readings += world.range_and_bearing(r).size();
  EXPECT_GT(readings, 400U);
  EXPECT_EQ(allocations_during([&] {
              for (int i = 0; i < 50; ++i) world.step({}, sent);
            }),
            0U);
}

// Deliveries are copied into reused inbox slots: once the slots and their payload buffers have
// grown, repeating the same traffic allocates nothing.
TEST(RobotAllocationTest, InboxesReuseTheirSlots) {
  PluginLoader loader;
  RobotSettings settings = make_settings(loader, 20, 10.0, 10.0);
  RobotWorld world(settings, loader);
  std::vector<Delivery> deliveries;
  for (RobotId r = 0; r < 20; ++r) {
    for (int k = 0; k < 3; ++k) {
      Delivery delivery;
      delivery.source = (r + 1) % 20;
      delivery.destination = r;
      delivery.receiver = r;
      delivery.payload.assign(256, std::byte{1});
      deliveries.push_back(delivery);
    }
  }
  std::vector<AppMessage> sent;
  world.step(deliveries, sent);
  EXPECT_EQ(allocations_during([&] {
              for (int i = 0; i < 50; ++i) world.step(deliveries, sent);
            }),
            0U);
}

}  // namespace
}  // namespace swarmnet
