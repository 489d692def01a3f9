#include "event_placement.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace swarmnet::task_events {

namespace {

// Draws per event before giving up: obstacles would have to cover nearly all the room.
constexpr int kPlacementAttempts = 10000;

bool inside_obstacle(const Arena& arena, const Vec2& point) {
  return std::any_of(arena.obstacles.begin(), arena.obstacles.end(),
                     [&](const Rect& r) { return r.contains(point); });
}

}  // namespace

std::vector<TaskEvent> place_events(const Arena& arena, std::size_t count, double margin_m,
                                    std::uint32_t skill_types, RandomStream& random) {
  if (2.0 * margin_m >= arena.width_m || 2.0 * margin_m >= arena.height_m) {
    throw std::invalid_argument(
        "event_margin_m = " + std::to_string(margin_m) + " m leaves no room for events in a " +
        std::to_string(arena.width_m) + " x " + std::to_string(arena.height_m) + " m arena");
  }
  std::vector<TaskEvent> events(count);
  for (std::size_t i = 0; i < count; ++i) {
    TaskEvent& event = events[i];
    event.id = static_cast<std::uint32_t>(i);
    int attempt = 0;
    do {
      if (++attempt > kPlacementAttempts) {
        throw std::invalid_argument("no place outside the obstacles found for event " +
                                    std::to_string(i) + " after " +
                                    std::to_string(kPlacementAttempts) + " draws");
      }
      event.position = Vec2(random.uniform(margin_m, arena.width_m - margin_m),
                            random.uniform(margin_m, arena.height_m - margin_m));
    } while (inside_obstacle(arena, event.position));
    event.skill = static_cast<std::uint32_t>(random.below(skill_types));
  }
  return events;
}

std::vector<std::vector<std::uint32_t>> draw_skills(std::size_t robots, std::uint32_t per_robot,
                                                    std::uint32_t skill_types,
                                                    RandomStream& random) {
  std::vector<std::vector<std::uint32_t>> skills(robots);
  std::vector<std::uint32_t> pool(skill_types);
  for (auto& own : skills) {
    // A partial Fisher-Yates shuffle: the first per_robot entries are a uniform sample.
    std::iota(pool.begin(), pool.end(), 0U);
    for (std::uint32_t k = 0; k < per_robot; ++k) {
      const auto j = k + static_cast<std::uint32_t>(random.below(skill_types - k));
      std::swap(pool[k], pool[j]);
    }
    own.assign(pool.begin(), pool.begin() + per_robot);
    std::sort(own.begin(), own.end());
  }
  return skills;
}

}  // namespace swarmnet::task_events
