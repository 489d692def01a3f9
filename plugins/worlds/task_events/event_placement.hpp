// Where the task_events world puts its events and which skills its robots get.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/random.hpp"
#include "task_event.hpp"

namespace swarmnet::task_events {

// `count` events uniformly at random in the arena shrunk by `margin_m` on every side, none inside
// an obstacle, each with a skill drawn uniformly from [0, skill_types). Throws
// std::invalid_argument when the margin leaves no room, or when no free place is found for an
// event after many draws (obstacles covering nearly everything).
std::vector<TaskEvent> place_events(const Arena& arena, std::size_t count, double margin_m,
                                    std::uint32_t skill_types, RandomStream& random);

// `per_robot` distinct skills out of [0, skill_types) for each of `robots` robots, uniformly at
// random, each robot's ascending. per_robot <= skill_types.
std::vector<std::vector<std::uint32_t>> draw_skills(std::size_t robots, std::uint32_t per_robot,
                                                    std::uint32_t skill_types,
                                                    RandomStream& random);

}  // namespace swarmnet::task_events
