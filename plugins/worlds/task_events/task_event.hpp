// One event of the task_events world: where it is, what it needs, how far its service has got.
#pragma once

#include <cstdint>

#include "swarmnet/vector.hpp"

namespace swarmnet::task_events {

struct TaskEvent {
  std::uint32_t id = 0;  // its index in the world's list
  Vec2 position = Vec2::Zero();
  std::uint32_t skill = 0;    // the skill type its robots must have
  std::uint32_t waiting = 0;  // joined robots with the skill inside the service radius, last step
  double service_elapsed_s = 0.0;  // how long at least `required` robots have been there together
  bool serviced = false;
};

}  // namespace swarmnet::task_events
