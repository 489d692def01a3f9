// world_view: the task_events world's readings, parsed. The layouts are the world's (see
// task_allocation.hpp); a reading of an unexpected length is read as far as it goes (a truncated
// "events_in_view" entry is dropped, a short "battery" reads as full and not low), so that a
// malformed reading never stops a run.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "swarmnet/controller.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet::task_allocation {

struct Battery {
  double fraction = 1.0;
  bool low = false;
};

struct EventSighting {
  std::uint32_t id = 0;
  Vec2 position = Vec2::Zero();
  std::uint32_t skill = 0;
  std::uint32_t required = 0;
  std::uint32_t waiting = 0;
};

struct JoinStatus {
  std::uint32_t event = 0;
  std::uint32_t waiting = 0;
  double service_elapsed_s = 0.0;
};

struct Charger {
  Vec2 position = Vec2::Zero();
  double radius_m = 0.0;
};

// A non-negative small integer held in a double (ids, counts, skills).
[[nodiscard]] std::uint32_t to_count(double value);

[[nodiscard]] Battery read_battery(const RobotContext& robot);
[[nodiscard]] std::vector<std::uint32_t> read_skills(const RobotContext& robot);  // ascending
[[nodiscard]] std::vector<EventSighting> read_events_in_view(const RobotContext& robot);
[[nodiscard]] std::optional<JoinStatus> read_joined(const RobotContext& robot);
[[nodiscard]] Charger read_charger(const RobotContext& robot);

}  // namespace swarmnet::task_allocation
