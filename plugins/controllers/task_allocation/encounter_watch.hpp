// encounter_watch: which radio neighbours are new. A robot whose radio starts hearing someone it
// did not hear a moment ago has met a robot that may not know what it knows (it was out of
// range, or in another part of a split swarm, when the news was flooded).
#pragma once

#include <span>
#include <vector>

#include "swarmnet/radio_neighbor.hpp"

namespace swarmnet::task_allocation {

class EncounterWatch {
 public:
  // Whether `table` (RobotContext::neighbors(), ascending by id) holds a node that the table of
  // the previous call did not; remembers `table` for the next call. The first call compares
  // with an empty table.
  bool met_someone(std::span<const RadioNeighbor> table);

 private:
  std::vector<RobotId> previous_;  // ascending
};

}  // namespace swarmnet::task_allocation
