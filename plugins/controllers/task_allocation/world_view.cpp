#include "world_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarmnet::task_allocation {

std::uint32_t to_count(double value) {
  if (!(value > 0.0)) return 0;  // also NaN
  if (value >= static_cast<double>(std::numeric_limits<std::uint32_t>::max())) {
    return std::numeric_limits<std::uint32_t>::max();
  }
  return static_cast<std::uint32_t>(std::llround(value));
}

Battery read_battery(const RobotContext& robot) {
  const std::span<const double> r = robot.reading("battery");
  Battery battery;
  if (!r.empty()) battery.fraction = r[0];
  if (r.size() >= 2) battery.low = r[1] >= 0.5;
  return battery;
}

std::vector<std::uint32_t> read_skills(const RobotContext& robot) {
  const std::span<const double> r = robot.reading("skills");
  std::vector<std::uint32_t> skills;
  skills.reserve(r.size());
  for (const double s : r) skills.push_back(to_count(s));
  std::sort(skills.begin(), skills.end());
  return skills;
}

std::vector<EventSighting> read_events_in_view(const RobotContext& robot) {
  const std::span<const double> r = robot.reading("events_in_view");
  std::vector<EventSighting> events;
  events.reserve(r.size() / 6);
  for (std::size_t i = 0; i + 6 <= r.size(); i += 6) {
    EventSighting e;
    e.id = to_count(r[i]);
    e.position = Vec2(r[i + 1], r[i + 2]);
    e.skill = to_count(r[i + 3]);
    e.required = to_count(r[i + 4]);
    e.waiting = to_count(r[i + 5]);
    if (e.position.allFinite()) events.push_back(e);
  }
  return events;
}

std::optional<JoinStatus> read_joined(const RobotContext& robot) {
  const std::span<const double> r = robot.reading("joined");
  if (r.size() < 3) return std::nullopt;
  return JoinStatus{to_count(r[0]), to_count(r[1]), r[2]};
}

Charger read_charger(const RobotContext& robot) {
  const std::span<const double> r = robot.reading("charger");
  Charger charger;
  if (r.size() >= 3) {
    charger.position = Vec2(r[0], r[1]);
    charger.radius_m = r[2];
  }
  return charger;
}

}  // namespace swarmnet::task_allocation
