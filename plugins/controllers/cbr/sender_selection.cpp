#include "sender_selection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "swarmnet/random.hpp"

namespace swarmnet::cbr {

std::uint32_t sender_count(double fraction, std::uint32_t robot_count, bool fixed_destination) {
  const auto wanted =
      static_cast<std::uint32_t>(std::floor(fraction * static_cast<double>(robot_count) + 0.5));
  std::uint32_t eligible = robot_count;
  if (fixed_destination) eligible = robot_count > 0 ? robot_count - 1 : 0;
  if (!fixed_destination && robot_count < 2) eligible = 0;
  return std::min(wanted, eligible);
}

std::vector<RobotId> choose_senders(std::uint64_t shared_seed, std::uint32_t robot_count,
                                    std::uint32_t count, std::optional<RobotId> excluded) {
  std::vector<RobotId> ids;
  ids.reserve(robot_count);
  for (RobotId id = 0; id < robot_count; ++id) {
    if (id != excluded) ids.push_back(id);
  }
  count = std::min<std::uint32_t>(count, static_cast<std::uint32_t>(ids.size()));
  // Forward Fisher-Yates, stopped after `count` swaps: positions 0..count-1 are final then.
  RandomStream random(shared_seed);
  for (std::uint32_t i = 0; i < count; ++i) {
    const auto j = i + static_cast<std::uint32_t>(random.below(ids.size() - i));
    std::swap(ids[i], ids[j]);
  }
  ids.resize(count);
  return ids;
}

}  // namespace swarmnet::cbr
