#include "encounter_watch.hpp"

#include <algorithm>

namespace swarmnet::task_allocation {

bool EncounterWatch::met_someone(std::span<const RadioNeighbor> table) {
  bool met = false;
  std::vector<RobotId> current;
  current.reserve(table.size());
  for (const RadioNeighbor& neighbor : table) {
    current.push_back(neighbor.id);
    met = met || !std::binary_search(previous_.begin(), previous_.end(), neighbor.id);
  }
  previous_ = std::move(current);
  return met;
}

}  // namespace swarmnet::task_allocation
