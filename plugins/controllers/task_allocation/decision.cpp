#include "decision.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace swarmnet::task_allocation {

namespace {

bool has_skill(std::span<const std::uint32_t> skills, std::uint32_t skill) {
  return std::binary_search(skills.begin(), skills.end(), skill);
}

bool shunned(const DecisionInput& input, std::uint32_t id) {
  if (input.shunned_until == nullptr) return false;
  const auto it = input.shunned_until->find(id);
  return it != input.shunned_until->end() && input.now < it->second;
}

}  // namespace

bool under_served(const KnownEvent& event, RobotId self) {
  const auto own = event.going.find(self);
  std::uint64_t others = 0;
  for (const auto& [robot, stamp] : event.going) {
    if (robot == self) continue;
    if (own == event.going.end() || stamp < own->second) ++others;
  }
  return event.required > event.waiting + others;
}

std::optional<std::uint32_t> decide(const DecisionInput& input, RandomStream& random) {
  std::optional<std::uint32_t> closest;
  double closest_m = std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> others;
  for (const auto& [id, event] : input.memory->events()) {
    if (event.handled || !has_skill(input.skills, event.skill) || shunned(input, id)) continue;
    others.push_back(id);
    if (!under_served(event, input.self)) continue;
    const double distance_m = (event.position - input.position).norm();
    if (distance_m < closest_m) {
      closest_m = distance_m;
      closest = id;
    }
  }
  if (closest) return closest;
  if (others.empty() || !random.bernoulli(input.other_event_probability)) return std::nullopt;
  return others[random.below(others.size())];
}

}  // namespace swarmnet::task_allocation
